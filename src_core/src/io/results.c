#include "sbc/results.h"

const char sbc_csv_header[] = "increment,F11,F12,F21,F22,P11,P12,P21,P22,sigma11,sigma12,sigma21,sigma22,"
                              "overlap_mean,rotation_mean,iterations,relax_steps,r_force,r_moment,r_deformation,"
                              "unbalanced,frame_residual,hill_mandel";

sbc_status sbc_csv_open(FILE **fp, const char *path, sbc_error *err)
{
    *fp = fopen(path, "w");
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
    int k, ok;
    ok = fprintf(fp, "%d", r->increment) > 0;
    for (k = 0; k < 4; ++k) ok = ok && fprintf(fp, ",%.17g", r->F[k]) > 0;
    for (k = 0; k < 4; ++k) ok = ok && fprintf(fp, ",%.17g", r->P[k]) > 0;
    for (k = 0; k < 4; ++k) ok = ok && fprintf(fp, ",%.17g", r->sigma[k]) > 0;
    ok = ok && fprintf(fp, ",%.17g,%.17g,%d,%ld,%.17g,%.17g,%.17g,%.6g,%.6g,%.6g\n", r->overlap_mean,
                       r->rotation_mean, r->iterations, r->relax_steps, r->r_force, r->r_moment, r->r_deformation,
                       r->unbalanced, r->frame_residual, r->hill_mandel) > 0;
    if (!ok || fflush(fp) != 0)
        return sbc_fail(err, SBC_ERR_IO, "results file: write failed at increment %d", r->increment);
    return SBC_OK;
}
