#include "sbc/status.h"

#include <stdarg.h>
#include <stdio.h>

const char *sbc_status_string(sbc_status status)
{
    switch (status) {
    case SBC_OK: return "ok";
    case SBC_ERR_INPUT: return "input error";
    case SBC_ERR_FRAME: return "frame error";
    case SBC_ERR_GEOMETRY: return "geometry error";
    case SBC_ERR_DIVERGED: return "diverged";
    case SBC_ERR_NUMERIC: return "non-finite value";
    case SBC_ERR_IO: return "i/o error";
    case SBC_ERR_NOMEM: return "out of memory";
    }
    return "unknown status";
}

sbc_status sbc_fail(sbc_error *err, sbc_status status, const char *fmt, ...)
{
    if (err) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(err->message, sizeof err->message, fmt, ap);
        va_end(ap);
        err->status = status;
    }
    return status;
}

void sbc_error_clear(sbc_error *err)
{
    if (err) {
        err->status = SBC_OK;
        err->message[0] = '\0';
    }
}
