/* Replays inputs through one harness without libFuzzer (gcc, ASan + UBSan in
 * make check): every FILE, and every file of every FOLDER, once.
 *   fuzz_NAME_replay FILE|FOLDER ... */
#define _POSIX_C_SOURCE 200809L
#include "fuzz.h"

#include <dirent.h>
#include <unistd.h>
#include <sys/stat.h>

static long replayed;

static void replay_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    unsigned char *data = NULL;
    size_t size = 0, cap = 0, got;
    if (!fp) {
        fprintf(stderr, "replay: cannot open '%s'\n", path);
        exit(2);
    }
    do {
        if (size == cap && !(data = realloc(data, cap = cap ? 2 * cap : 4096)))
            abort();
        got = fread(data + size, 1, cap - size, fp);
        size += got;
    } while (got > 0);
    fclose(fp);
    LLVMFuzzerTestOneInput(data, size);
    free(data);
    ++replayed;
}

static void replay(const char *path)
{
    struct stat st;
    DIR *d;
    struct dirent *e;
    if (stat(path, &st) != 0) {
        fprintf(stderr, "replay: no file or folder '%s'\n", path);
        exit(2);
    }
    if (!S_ISDIR(st.st_mode)) {
        replay_file(path);
        return;
    }
    if (!(d = opendir(path)))
        exit(2);
    while ((e = readdir(d))) {
        char full[4096];
        if (e->d_name[0] == '.')
            continue;
        snprintf(full, sizeof full, "%s/%s", path, e->d_name);
        replay(full);
    }
    closedir(d);
}

int main(int argc, char **argv)
{
    int k;
    char cwd[4096];
    /* the harness moves into a private folder: resolve the paths first */
    for (k = 1; k < argc; ++k)
        if (argv[k][0] != '/' && getcwd(cwd, sizeof cwd)) {
            char *full = malloc(strlen(cwd) + strlen(argv[k]) + 2);
            if (!full)
                abort();
            sprintf(full, "%s/%s", cwd, argv[k]);
            argv[k] = full;
        }
    for (k = 1; k < argc; ++k)
        replay(argv[k]);
    printf("%s: %ld inputs replayed, none broke the contract\n", argv[0], replayed);
    return 0;
}
