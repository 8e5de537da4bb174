#include "sbc/results.h"
#include "sbc/output_file.h"
#include <math.h>

const char sbc_csv_header[] = "increment,F11,F12,F21,F22,P11,P12,P21,P22,sigma11,sigma12,sigma21,sigma22,"
                              "overlap_mean,rotation_mean,iterations,relax_steps,r_force,r_moment,r_deformation,"
                              "unbalanced,frame_residual,hill_mandel";

sbc_status sbc_csv_open(FILE **fp, const char *path, sbc_error *err)
{
    *fp = sbc_output_open(path);
    if (!*fp)
        return sbc_fail(err, SBC_ERR_IO, "keyword 'file': cannot open '%s' for writing", path);
    fprintf(*fp, "%s\n", sbc_csv_header);
    fflush(*fp);
    return SBC_OK;
}

sbc_status sbc_csv_append(FILE **fp, const char *path, sbc_error *err)
{
    *fp = fopen(path, "a");
    if (!*fp)
        return sbc_fail(err, SBC_ERR_IO, "keyword 'file': cannot open '%s' for appending", path);
    if (ftell(*fp) == 0) {
        fprintf(*fp, "%s\n", sbc_csv_header);
        fflush(*fp);
    }
    return SBC_OK;
}

sbc_status sbc_csv_write(FILE *fp, const sbc_result *r, sbc_error *err)
{
    /* one row, formatted whole and written in one call with its newline: a row
       is complete only with its newline, so a write error cannot leave a torn
       row that reads as a whole one (readers drop a last line without it) */
    const double check[21] = {r->F[0], r->F[1], r->F[2], r->F[3], r->P[0], r->P[1], r->P[2], r->P[3],
                              r->sigma[0], r->sigma[1], r->sigma[2], r->sigma[3], r->overlap_mean,
                              r->rotation_mean, r->r_force, r->r_moment, r->r_deformation, r->unbalanced,
                              r->frame_residual, r->hill_mandel, 0.0};
    char row[2048];
    int k, n = snprintf(row, sizeof row, "%d", r->increment);
    for (k = 0; k < 20; ++k)
        if (!isfinite(check[k]))
            return sbc_fail(err, SBC_ERR_NUMERIC, "results file: increment %d has a non-finite value (column %d); the "
                            "row is not written", r->increment, k + 2);
    for (k = 0; k < 4; ++k) n += snprintf(row + n, sizeof row - (size_t)n, ",%.17g", r->F[k]);
    for (k = 0; k < 4; ++k) n += snprintf(row + n, sizeof row - (size_t)n, ",%.17g", r->P[k]);
    for (k = 0; k < 4; ++k) n += snprintf(row + n, sizeof row - (size_t)n, ",%.17g", r->sigma[k]);
    n += snprintf(row + n, sizeof row - (size_t)n, ",%.17g,%.17g,%d,%ld,%.17g,%.17g,%.17g,%.6g,%.6g,%.6g\n",
                  r->overlap_mean, r->rotation_mean, r->iterations, r->relax_steps, r->r_force, r->r_moment,
                  r->r_deformation, r->unbalanced, r->frame_residual, r->hill_mandel);
    if (n <= 0 || (size_t)n >= sizeof row || fwrite(row, 1, (size_t)n, fp) != (size_t)n || fflush(fp) != 0)
        return sbc_fail(err, SBC_ERR_IO, "results file: write failed at increment %d", r->increment);
    return SBC_OK;
}
