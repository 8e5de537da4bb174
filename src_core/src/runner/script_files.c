#define _POSIX_C_SOURCE 200809L
/* The runner's files: an output may not overwrite the script, a packing the
 * script read, or an output an earlier command of the script wrote. */
#include "script_state.h"

#include <string.h>
#include <sys/stat.h>

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
