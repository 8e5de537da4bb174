#define _XOPEN_SOURCE 700
/* The runner's files: an output may not overwrite the script, a file the
 * script read, or an output an earlier command of the script or another
 * output of the same run writes. */
#include "script_state.h"
#include "sbc/embedded/output_file.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* the identity of an existing file, 0 if there is none */
static int identify(const char *path, sbc_file_id *id)
{
    struct stat st;
    if (!path || stat(path, &st) != 0)
        return 0;
    id->dev = (unsigned long long)st.st_dev;
    id->ino = (unsigned long long)st.st_ino;
    return 1;
}

void sbc_script_files_note(script *s, const char *path, const char *role)
{
    sbc_file_id id;
    if (s->nfiles >= SBC_SCRIPT_FILES || !identify(path, &id))
        return;
    id.line = s->line;
    snprintf(id.role, sizeof id.role, "%s", role);
    snprintf(id.path, sizeof id.path, "%s", path);
    s->files[s->nfiles++] = id;
}

sbc_status sbc_script_files_check(script *s, const char *path, const char *what, sbc_error *err)
{
    sbc_file_id id;
    int k;
    if (!identify(path, &id))
        return SBC_OK;
    if (s->name && identify(s->name, &s->script_id) && s->script_id.dev == id.dev && s->script_id.ino == id.ino)
        return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is this script; choose another file name", what, path);
    for (k = 0; k < s->nfiles; ++k)
        if (s->files[k].dev == id.dev && s->files[k].ino == id.ino)
            return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is the %s of line %d; choose another file name", what, path,
                            s->files[k].role, s->files[k].line);
    return SBC_OK;
}

/* path with its folder resolved (the folder need not exist), for comparing
   names of files that may not exist yet */
static void canonical(const char *path, char *out, size_t size)
{
    const char *slash = strrchr(path, '/');
    char folder[PATH_MAX], real[PATH_MAX + 1];
    size_t len = slash ? (size_t)(slash - path) : 1;
    if (!slash)
        strcpy(folder, ".");
    else if (len == 0)
        strcpy(folder, "/");
    else {
        if (len >= sizeof folder) len = sizeof folder - 1;
        memcpy(folder, path, len);
        folder[len] = '\0';
    }
    if (realpath(folder, real)) {
        const size_t used = strcmp(real, "/") == 0 ? 0 : strlen(real);
        const char *base = slash ? slash + 1 : path;
        if (used + 1 + strlen(base) < size) {
            memcpy(out, real, used);
            out[used] = '/';
            strcpy(out + used + 1, base);
        } else
            snprintf(out, size, "%s", path);
    } else
        snprintf(out, size, "%s", path);
}

/* one output of a run: a file, or a family PREFIX MIDDLE 000000 SUFFIX */
typedef struct output {
    const char *what;             /* for the message */
    char name[PATH_MAX];          /* the file, or the family's prefix, canonical */
    const char *shown;            /* as the script gives it */
    const char *middle[2], *suffix;
    sbc_output_kind kind;
} output;

/* does the canonical file name belong to o? */
static int belongs(const output *o, const char *file)
{
    size_t n = strlen(o->name), digits;
    const char *rest;
    int m;
    if (!o->suffix)
        return strcmp(o->name, file) == 0;
    if (strncmp(o->name, file, n) != 0)
        return 0;
    for (m = 0; m < 2 && o->middle[m]; ++m) {
        size_t mid = strlen(o->middle[m]);
        if (strncmp(file + n, o->middle[m], mid) != 0)
            continue;
        rest = file + n + mid;
        for (digits = 0; rest[digits] >= '0' && rest[digits] <= '9'; ++digits) {}
        if (digits >= 6 && strcmp(rest + digits, o->suffix) == 0)
            return 1;
    }
    return 0;
}

/* the first file of a family, to probe */
static void first_file(const output *o, char *out, size_t size)
{
    if (o->suffix)
        snprintf(out, size, "%s%s000000%s", o->shown, o->middle[0], o->suffix);
    else
        snprintf(out, size, "%s", o->shown);
}

sbc_status sbc_script_outputs_check(script *s, sbc_error *err)
{
    output out[5];
    int n = 0, a, b, k;
    char file[PATH_MAX], other[PATH_MAX];
    sbc_status st;
    memset(out, 0, sizeof out);
    if (s->settings.file[0]) {
        out[n].what = "servo_bc keyword 'file'", out[n].shown = s->settings.file, out[n].kind = SBC_OUTPUT_RESULTS;
        ++n;
    }
    if (s->settings.tangent) {
        out[n].what = "servo_bc keyword 'tangent'", out[n].shown = s->settings.tangent_file;
        out[n].kind = SBC_OUTPUT_RESULTS;
        ++n;
    }
    if (s->plot[0]) {
        out[n].what = "plot", out[n].shown = s->plot, out[n].kind = SBC_OUTPUT_SVG;
        ++n;
    }
    if (s->vtk_every) {
        out[n].what = "vtk", out[n].shown = s->vtk_prefix, out[n].kind = SBC_OUTPUT_VTK;
        out[n].middle[0] = s->bpm ? "_spheres_" : "_particles_"; /* after 'dimension 3': the sphere run's family */
        out[n].middle[1] = s->bpm ? "_frame_" : "_contacts_", out[n].suffix = ".vtk";
        ++n;
    }
    if (s->network_every) {
        out[n].what = "network", out[n].shown = s->network_prefix, out[n].kind = SBC_OUTPUT_SVG;
        out[n].middle[0] = "_", out[n].suffix = ".svg";
        ++n;
    }
    for (a = 0; a < n; ++a)
        canonical(out[a].shown, out[a].name, sizeof out[a].name);
    for (a = 0; a < n; ++a) {
        /* the script and the files read or written before */
        if (s->name) {
            canonical(s->name, file, sizeof file);
            if (belongs(&out[a], file))
                return out[a].suffix ? sbc_fail(err, SBC_ERR_INPUT, "%s '%s' would write '%s', which is this script; "
                                                "choose another name", out[a].what, out[a].shown, s->name)
                                     : sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is this script; choose another file name",
                                                out[a].what, out[a].shown);
        }
        for (k = 0; k < s->nfiles; ++k) {
            canonical(s->files[k].path, file, sizeof file);
            if (!belongs(&out[a], file))
                continue;
            if (out[a].suffix)
                return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' would write '%s', which is the %s of line %d; choose "
                                "another name", out[a].what, out[a].shown, s->files[k].path, s->files[k].role,
                                s->files[k].line);
            return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' is the %s of line %d; choose another file name", out[a].what,
                            out[a].shown, s->files[k].role, s->files[k].line);
        }
        if (!out[a].suffix && (st = sbc_script_files_check(s, out[a].shown, out[a].what, err)) != SBC_OK)
            return st;
        /* the run's other outputs */
        for (b = 0; b < n; ++b) {
            if (b == a || out[b].suffix)
                continue; /* two families differ in their suffix */
            if (belongs(&out[a], out[b].name))
                return sbc_fail(err, SBC_ERR_INPUT, "%s '%s' and %s '%s' would write the same file; choose another "
                                "name for one", out[b].what, out[b].shown, out[a].what, out[a].shown);
        }
        if (s->check) {
            first_file(&out[a], other, sizeof other);
            if ((st = sbc_output_probe(other, out[a].kind, out[a].what, err)) != SBC_OK)
                return st;
        }
    }
    return SBC_OK;
}
