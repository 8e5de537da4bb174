#define _POSIX_C_SOURCE 200809L
/* servo_bc: opening an output file (output_file.h). */
#include "sbc/embedded/output_file.h"

#include <errno.h>
#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* how each kind's files begin: `head` at the start of the first line, or
   `inside` anywhere in it */
static const struct {
    const char *name, *head, *inside;
} kinds[] = {
    [SBC_OUTPUT_RESULTS] = {"results file", "increment,", NULL},
    [SBC_OUTPUT_SERIES] = {"time series", "step,", NULL},
    [SBC_OUTPUT_VTK] = {"VTK file", "# vtk DataFile", NULL},
    [SBC_OUTPUT_SVG] = {"SVG picture", "<svg", NULL},
    [SBC_OUTPUT_PACKING] = {"packing", NULL, "servo_bc packing"},
    [SBC_OUTPUT_DECK] = {"deck", NULL, "(servo-bc --decks)"},
};

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

/* the folder part of path ("" when there is none), malloc'ed */
static char *folder_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t len = slash && slash != path ? (size_t)(slash - path) : 0;
    char *folder = malloc(len + 1);
    if (folder) {
        memcpy(folder, path, len);
        folder[len] = '\0';
    }
    return folder;
}

/* the first line of text, printable, for a message */
static void first_line(const char *text, char *out, size_t size)
{
    size_t k;
    for (k = 0; k + 1 < size && text[k] && text[k] != '\n' && text[k] != '\r'; ++k)
        out[k] = (text[k] >= 32 && text[k] < 127) ? text[k] : '?';
    out[k] = '\0';
}

sbc_status sbc_output_owned(const char *path, sbc_output_kind kind, const char *what, sbc_error *err)
{
    struct stat st;
    char head[256], line[48];
    size_t n;
    FILE *fp;
    if (stat(path, &st) != 0)
        return SBC_OK;
    if (S_ISDIR(st.st_mode))
        return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': it is a folder", what, path);
    if (!S_ISREG(st.st_mode) || st.st_size == 0)
        return SBC_OK; /* /dev/null, a pipe; an empty file */
    if (!(fp = fopen(path, "rb")))
        return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': it exists and cannot be read to see whether "
                        "servo_bc wrote it (%s)", what, path, strerror(errno));
    n = fread(head, 1, sizeof head - 1, fp);
    fclose(fp);
    head[n] = '\0';
    first_line(head, line, sizeof line);
    {
        const char *eol = strchr(head, '\n');
        const int begins = kinds[kind].head && strncmp(head, kinds[kind].head, strlen(kinds[kind].head)) == 0;
        const char *in = kinds[kind].inside ? strstr(head, kinds[kind].inside) : NULL;
        if (begins || (in && (!eol || in < eol)))
            return SBC_OK;
    }
    return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': it exists and is not a servo_bc %s (its first line is "
                    "'%s'); servo_bc overwrites only files it wrote: remove it or choose another name",
                    what, path, kinds[kind].name, line);
}

/* the write lock on fd, or the message naming who holds it */
static sbc_status lock(int fd, const char *path, const char *what, sbc_error *err)
{
    struct flock fl;
    memset(&fl, 0, sizeof fl);
    fl.l_type = F_WRLCK;
    fl.l_whence = SEEK_SET;
    if (fcntl(fd, F_SETLK, &fl) == 0)
        return SBC_OK;
    if (errno != EACCES && errno != EAGAIN)
        return SBC_OK; /* a file system without locks: nothing to hold */
    memset(&fl, 0, sizeof fl);
    fl.l_type = F_WRLCK;
    fl.l_whence = SEEK_SET;
    if (fcntl(fd, F_GETLK, &fl) == 0 && fl.l_type != F_UNLCK)
        return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': process %ld is writing it (a run writes its files "
                        "alone); wait for it or choose another name", what, path, (long)fl.l_pid);
    return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': another process is writing it (a run writes its files "
                    "alone); wait for it or choose another name", what, path);
}

/* the file opened (created, with its folders) and locked; truncated unless keep */
static FILE *open_locked(const char *path, sbc_output_kind kind, const char *what, int keep, sbc_error *err)
{
    char *folder;
    int fd, rc;
    struct stat st;
    FILE *fp;
    if (!path[0]) {
        sbc_fail(err, SBC_ERR_IO, "%s: the file name is empty", what);
        return NULL;
    }
    if (sbc_output_owned(path, kind, what, err) != SBC_OK)
        return NULL;
    if (!(folder = folder_of(path))) {
        sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory", what);
        return NULL;
    }
    rc = folder[0] ? sbc_output_folder(folder) : 0;
    if (rc != 0) {
        sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': cannot make the folder '%s' (%s)", what, path, folder,
                 strerror(errno));
        free(folder);
        return NULL;
    }
    free(folder);
    if ((fd = open(path, (keep ? O_RDWR : O_WRONLY) | O_CREAT, 0666)) < 0) {
        sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s' (%s)", what, path, strerror(errno));
        return NULL;
    }
    if (lock(fd, path, what, err) != SBC_OK) {
        close(fd);
        return NULL;
    }
    if (!keep && fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && ftruncate(fd, 0) != 0) {
        sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s' (%s)", what, path, strerror(errno));
        close(fd);
        return NULL;
    }
    if (!(fp = fdopen(fd, keep ? "r+" : "w"))) {
        sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s' (%s)", what, path, strerror(errno));
        close(fd);
        return NULL;
    }
    return fp;
}

FILE *sbc_output_open(const char *path, sbc_output_kind kind, const char *what, sbc_error *err)
{
    return open_locked(path, kind, what, 0, err);
}

FILE *sbc_output_update(const char *path, sbc_output_kind kind, const char *what, sbc_error *err)
{
    return open_locked(path, kind, what, 1, err);
}

sbc_status sbc_output_probe(const char *path, sbc_output_kind kind, const char *what, sbc_error *err)
{
    char *folder, *made = NULL;
    struct stat st;
    sbc_status status = SBC_OK;
    int fd, existed;
    if (!path[0])
        return sbc_fail(err, SBC_ERR_IO, "%s: the file name is empty", what);
    if ((status = sbc_output_owned(path, kind, what, err)) != SBC_OK)
        return status;
    existed = stat(path, &st) == 0;
    if (!(folder = folder_of(path)))
        return sbc_fail(err, SBC_ERR_NOMEM, "%s: out of memory", what);
    if (folder[0] && stat(folder, &st) != 0) {
        /* the first missing folder of the path: made now, removed below */
        size_t k, len = strlen(folder);
        for (k = 1; k <= len; ++k)
            if (folder[k] == '/' || folder[k] == '\0') {
                const char keep = folder[k];
                folder[k] = '\0';
                if (stat(folder, &st) != 0) {
                    made = malloc(k + 1);
                    if (made) memcpy(made, folder, k + 1);
                    folder[k] = keep;
                    break;
                }
                folder[k] = keep;
            }
        if (!made || sbc_output_folder(folder) != 0)
            status = sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s': cannot make the folder '%s' (%s)", what, path,
                              folder, made ? strerror(errno) : "out of memory");
    }
    if (status == SBC_OK) {
        if ((fd = open(path, O_WRONLY | O_CREAT, 0666)) < 0)
            status = sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s' (%s)", what, path, strerror(errno));
        else {
            status = lock(fd, path, what, err);
            close(fd);
            if (!existed)
                unlink(path);
        }
    }
    if (made) { /* remove what the probe made, deepest first */
        for (;;) {
            char *slash;
            rmdir(folder);
            if (strcmp(folder, made) == 0 || !(slash = strrchr(folder, '/')))
                break;
            *slash = '\0';
        }
        free(made);
    }
    free(folder);
    return status;
}

sbc_status sbc_output_append(FILE *fp, const char *text, size_t n, const char *path, const char *what,
                             const char *row, sbc_error *err)
{
    const int fd = fileno(fp);
    size_t done = 0;
    off_t at;
    if (fflush(fp) != 0 || (at = lseek(fd, 0, SEEK_END)) < 0)
        return sbc_fail(err, SBC_ERR_IO, "%s '%s': cannot write %s (%s)", what, path, row, strerror(errno));
    while (done < n) {
        const ssize_t w = write(fd, text + done, n - done);
        if (w < 0 && errno == EINTR)
            continue;
        if (w <= 0) {
            const int why = w < 0 ? errno : ENOSPC;
            if (ftruncate(fd, at) == 0)
                lseek(fd, at, SEEK_SET);
            return sbc_fail(err, SBC_ERR_IO, "%s '%s': cannot write %s (%s); the file ends with the rows before it",
                            what, path, row, strerror(why));
        }
        done += (size_t)w;
    }
    return SBC_OK;
}

sbc_status sbc_output_close(FILE *fp, const char *path, const char *what, sbc_error *err)
{
    int why = 0;
    errno = 0;
    if (fflush(fp) != 0 || ferror(fp))
        why = errno ? errno : EIO;
    if (fclose(fp) != 0 && !why)
        why = errno ? errno : EIO;
    if (!why)
        return SBC_OK;
    remove(path);
    return sbc_fail(err, SBC_ERR_IO, "%s: cannot write '%s' (%s); the partial file is removed", what, path,
                    strerror(why));
}
