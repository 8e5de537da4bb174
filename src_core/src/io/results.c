#define _POSIX_C_SOURCE 200809L
/* servo_bc: the results file (results.h). */
#include "sbc/results.h"
#include "sbc/columns.h"
#include "sbc/embedded/output_file.h"

#include <errno.h>
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <unistd.h>

static const char what[] = "keyword 'file'";

/* text[0..n) appended whole or not at all (sbc_output_append): the file never ends in a torn row */
static sbc_status put(sbc_csv *csv, const char *text, size_t n, int increment, sbc_error *err)
{
    char row[64];
    if (increment < 0)
        snprintf(row, sizeof row, "the header");
    else
        snprintf(row, sizeof row, "the row of increment %d", increment);
    return sbc_output_append(csv->fp, text, n, csv->path, "results file", row, err);
}

static sbc_status begin(sbc_csv *csv, const char *path, int dim, FILE *fp, sbc_error *err)
{
    char line[SBC_COLUMNS * 32];
    const int n = sbc_columns_header(dim, line, sizeof line - 1);
    csv->fp = fp;
    snprintf(csv->path, sizeof csv->path, "%s", path);
    line[n] = '\n';
    return put(csv, line, (size_t)n + 1, -1, err);
}

sbc_status sbc_csv_open(sbc_csv *csv, const char *path, int dim, sbc_error *err)
{
    FILE *fp = sbc_output_open(path, SBC_OUTPUT_RESULTS, what, err);
    csv->fp = NULL;
    if (!fp)
        return err->status;
    return begin(csv, path, dim, fp, err);
}

sbc_status sbc_csv_resume(sbc_csv *csv, const char *path, int dim, int next, int *kept, sbc_error *err)
{
    FILE *fp = sbc_output_update(path, SBC_OUTPUT_RESULTS, what, err);
    char line[4096];
    long keep = 0;
    int rows = 0, first = 1;
    csv->fp = NULL;
    if (kept) *kept = 0;
    if (!fp)
        return err->status;
    while (fgets(line, sizeof line, fp)) {
        const size_t len = strlen(line);
        char *end;
        long inc;
        if (len == 0 || line[len - 1] != '\n')
            break; /* a last line without its newline is no row */
        if (first) {
            first = 0;
            keep = ftell(fp);
            continue;
        }
        inc = strtol(line, &end, 10);
        if (end == line || *end != ',' || inc >= next)
            break;
        keep = ftell(fp);
        ++rows;
    }
    csv->fp = fp;
    snprintf(csv->path, sizeof csv->path, "%s", path);
    if (first) /* empty or new */
        return begin(csv, path, dim, fp, err);
    if (fflush(fp) != 0 || ftruncate(fileno(fp), (off_t)keep) != 0 || fseek(fp, keep, SEEK_SET) != 0)
        return sbc_fail(err, SBC_ERR_IO, "results file '%s': cannot cut it back to increment %d (%s)", path, next - 1,
                        strerror(errno));
    if (kept) *kept = rows;
    return SBC_OK;
}

sbc_status sbc_csv_write(sbc_csv *csv, const sbc_result *r, sbc_error *err)
{
    static const char *const formats[] = {"%.0f", "%.17g", "%.6g"}; /* by sbc_column_format */
    double v[SBC_COLUMNS];
    char row[2048];
    const int count = sbc_column_values(r, v);
    int k, n = 0;
    for (k = 0; k < count; ++k)
        if (!isfinite(v[k]))
            return sbc_fail(err, SBC_ERR_NUMERIC, "results file '%s': increment %d has %s = %g; the row is not "
                            "written and the run stops", csv->path, r->increment, sbc_column_name(r->dim, k), v[k]);
    for (k = 0; k < count && n >= 0 && (size_t)n < sizeof row; ++k) {
        if (k)
            row[n++] = ',';
        n += snprintf(row + n, sizeof row - (size_t)n, formats[sbc_column_of(r->dim, k)->format], v[k]);
    }
    if (n >= 0 && (size_t)n + 1 < sizeof row)
        row[n++] = '\n';
    if (n <= 0 || (size_t)n >= sizeof row)
        return sbc_fail(err, SBC_ERR_IO, "results file '%s': the row of increment %d does not fit", csv->path,
                        r->increment);
    return put(csv, row, (size_t)n, r->increment, err);
}

void sbc_csv_close(sbc_csv *csv)
{
    if (csv->fp)
        fclose(csv->fp);
    csv->fp = NULL;
}

int sbc_result_line(const sbc_result *r, sbc_bc bc, int total, char *out, size_t cap)
{
    /* the component ij of F farthest from the identity, the layer's shear
       (2D F12, 3D F13) unless another is strictly farther; then sigma_ij
       after a companion: the layer's normal stress (2D sigma11, 3D sigma33)
       for a shear, the first other axis' normal stress for a stretch (a
       triaxial path: F33, sigma11, sigma33) */
    const int n = r->dim == 3 ? 2 : 0;
    int i = 0, j = r->dim == 3 ? 2 : 1, a, b, c;
    double far = fabs(r->F[SBC_IJ(i, j)]);
    char F[8], s1[8], s2[8];
    for (a = 0; a < r->dim; ++a)
        for (b = 0; b < r->dim; ++b)
            if (fabs(r->F[SBC_IJ(a, b)] - (a == b ? 1.0 : 0.0)) > far) {
                far = fabs(r->F[SBC_IJ(a, b)] - (a == b ? 1.0 : 0.0));
                i = a, j = b;
            }
    c = i != j ? n : i == 0 ? 1 : 0;
    return snprintf(out, cap,
                    "servo_bc %s: increment %d/%d %s %+.5f %s %+.6e %s %+.6e %s steps %ld iterations %d "
                    "unbalanced %.2g HM %.1e",
                    sbc_bc_name(bc), r->increment, total, sbc_tensor_component_name("F", i, j, F), r->F[SBC_IJ(i, j)],
                    sbc_tensor_component_name("sigma", c, c, s1), r->sigma[SBC_IJ(c, c)],
                    sbc_tensor_component_name("sigma", i, j, s2), r->sigma[SBC_IJ(i, j)],
                    r->dim == 3 ? "N/m^2" : "N/m", r->relax_steps, r->iterations, r->unbalanced, r->hill_mandel);
}
