/* servo-bc-plot: overlay columns of servo_bc CSV files in one SVG chart.
 *
 *   servo-bc-plot OUT.svg TITLE XLABEL YLABEL XCOL XSCALE YCOL YSCALE FILE LABEL [FILE LABEL ...]
 *
 * Plots YSCALE * YCOL against XSCALE * XCOL for every FILE (column names of
 * the CSV header, e.g. F12 -1 sigma11 -1.02e-7). */
#include "sbc/embedded/plot.h"
#include "sbc/settings.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct column_pair {
    double *x, *y;
    int n;
} column_pair;

static int column_index(char *header, const char *name)
{
    char *p = header;
    int k = 0;
    for (;;) {
        char *comma = strchr(p, ',');
        size_t len = comma ? (size_t)(comma - p) : strcspn(p, "\r\n");
        if (len == strlen(name) && strncmp(p, name, len) == 0)
            return k;
        if (!comma)
            return -1;
        p = comma + 1;
        ++k;
    }
}

static int read_columns(const char *path, const char *xcol, double xs, const char *ycol, double ys, column_pair *out)
{
    FILE *fp = fopen(path, "r");
    char line[8192];
    int ix, iy, cap = 0;
    memset(out, 0, sizeof *out);
    if (!fp) {
        fprintf(stderr, "ERROR: servo-bc-plot: cannot open '%s'\n", path);
        return 0;
    }
    if (!fgets(line, sizeof line, fp) || (ix = column_index(line, xcol)) < 0 || (iy = column_index(line, ycol)) < 0) {
        fprintf(stderr, "ERROR: servo-bc-plot: '%s' has no columns '%s' and '%s'\n", path, xcol, ycol);
        fclose(fp);
        return 0;
    }
    while (fgets(line, sizeof line, fp)) {
        char *p = line, *end;
        double vx = 0.0, vy = 0.0;
        int k;
        for (k = 0; *p; ++k) {
            double v = strtod(p, &end);
            if (k == ix) vx = v;
            if (k == iy) vy = v;
            p = strchr(end, ',');
            if (!p) break;
            ++p;
        }
        if (out->n == cap) {
            double *nx, *ny;
            cap = cap ? 2 * cap : 512;
            nx = realloc(out->x, sizeof(double) * (size_t)cap);
            if (nx) out->x = nx;
            ny = realloc(out->y, sizeof(double) * (size_t)cap);
            if (ny) out->y = ny;
            if (!nx || !ny) {
                fprintf(stderr, "ERROR: servo-bc-plot: out of memory reading '%s'\n", path);
                fclose(fp);
                return 0;
            }
        }
        out->x[out->n] = xs * vx;
        out->y[out->n++] = ys * vy;
    }
    fclose(fp);
    return 1;
}

int main(int argc, char **argv)
{
    sbc_series *series;
    column_pair *cols;
    sbc_error err;
    double xs, ys;
    int k, ns, ok = 1;
    static const char usage[] =
        "usage: servo-bc-plot OUT.svg TITLE XLABEL YLABEL XCOL XSCALE YCOL YSCALE FILE LABEL [FILE LABEL ...]\n"
        "  Draws YSCALE * YCOL against XSCALE * XCOL of every servo_bc CSV FILE, one curve named LABEL each,\n"
        "  into the SVG chart OUT.svg. XCOL, YCOL: column names of the CSV header (F12, sigma11, P12, ...);\n"
        "  the scales turn them into what the labels say, e.g.\n"
        "    servo-bc-plot s.svg '(P)' 'F12 (-)' 'sigma12 / kn (-)' F12 1 sigma12 1e-4 P.csv embedded\n";
    if (argc == 2 && (strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--help") == 0)) {
        fputs(usage, stdout);
        return 0;
    }
    if (argc < 11 || (argc - 9) % 2 != 0) {
        fprintf(stderr, "ERROR: servo-bc-plot: expected 10 arguments or more in pairs after the 8th, got %d\n%s",
                argc - 1, usage);
        return 2;
    }
    if (sbc_parse_real(argv[6], "XSCALE", &xs, &err) != SBC_OK || sbc_parse_real(argv[8], "YSCALE", &ys, &err) != SBC_OK) {
        fprintf(stderr, "ERROR: servo-bc-plot: %s\n", err.message);
        return 2;
    }
    ns = (argc - 9) / 2;
    series = calloc((size_t)ns, sizeof *series);
    cols = calloc((size_t)ns, sizeof *cols);
    for (k = 0; k < ns && ok; ++k) {
        ok = read_columns(argv[9 + 2 * k], argv[5], xs, argv[7], ys, &cols[k]);
        series[k].label = argv[10 + 2 * k];
        series[k].n = cols[k].n;
        series[k].x = cols[k].x;
        series[k].y = cols[k].y;
    }
    if (ok && sbc_plot_svg(argv[1], argv[2], argv[3], argv[4], ns, series, &err) != SBC_OK) {
        fprintf(stderr, "ERROR: servo-bc-plot: %s\n", err.message);
        ok = 0;
    }
    for (k = 0; k < ns; ++k) {
        free(cols[k].x);
        free(cols[k].y);
    }
    free(cols);
    free(series);
    return ok ? 0 : 1;
}
