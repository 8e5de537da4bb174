#define _POSIX_C_SOURCE 200809L
#include "sbc/output_file.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int sbc_output_folder(const char *path)
{
    size_t len = strlen(path), k;
    char *copy = malloc(len + 1);
    int rc = 0;
    if (!copy)
        return -1;
    memcpy(copy, path, len + 1);
    for (k = 1; k <= len && rc == 0; ++k)
        if (copy[k] == '/' || copy[k] == '\0') {
            const char keep = copy[k];
            struct stat st;
            copy[k] = '\0';
            if (stat(copy, &st) != 0)
                rc = mkdir(copy, 0777) == 0 || errno == EEXIST ? 0 : -1;
            else if (!S_ISDIR(st.st_mode)) {
                errno = ENOTDIR;
                rc = -1;
            }
            copy[k] = keep;
        }
    free(copy);
    return rc;
}

FILE *sbc_output_open(const char *path)
{
    const char *slash = strrchr(path, '/');
    if (slash && slash != path) {
        size_t len = (size_t)(slash - path);
        char *folder = malloc(len + 1);
        int rc;
        if (!folder)
            return NULL;
        memcpy(folder, path, len);
        folder[len] = '\0';
        rc = sbc_output_folder(folder);
        free(folder);
        if (rc != 0)
            return NULL;
    }
    return fopen(path, "w");
}
