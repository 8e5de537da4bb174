/* servo_bc: status codes and the error context.
 *
 * Every call that can fail returns an sbc_status; the message that explains it
 * is written into a caller-owned sbc_error (never into a global). */
#ifndef SBC_STATUS_H
#define SBC_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

typedef enum sbc_status {
    SBC_OK = 0,
    SBC_ERR_INPUT,     /* bad command, keyword or value */
    SBC_ERR_FRAME,     /* the boundary frame cannot be identified */
    SBC_ERR_GEOMETRY,  /* impossible state: det F <= 0, no contacts, ... */
    SBC_ERR_DIVERGED,  /* controller or relaxation did not converge */
    SBC_ERR_NUMERIC,   /* a non-finite value appeared */
    SBC_ERR_IO,        /* a file could not be read or written */
    SBC_ERR_NOMEM      /* allocation failed */
} sbc_status;

#define SBC_ERROR_LEN 512

typedef struct sbc_error {
    sbc_status status;
    char message[SBC_ERROR_LEN];
} sbc_error;

/* Short name of a status code, e.g. "input error". */
const char *sbc_status_string(sbc_status status);

/* Records status and a printf-style message in err (err may be NULL);
 * returns status so that callers can write `return sbc_fail(err, ...)`. */
sbc_status sbc_fail(sbc_error *err, sbc_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* Clears err to SBC_OK with an empty message. */
void sbc_error_clear(sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
