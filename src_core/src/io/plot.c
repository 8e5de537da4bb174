#include "sbc/embedded/plot.h"
#include "sbc/embedded/output_file.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#define W 720.0
#define H 480.0
#define LEFT 90.0
#define RIGHT 20.0
#define TOP 40.0
#define BOTTOM 60.0

/* A "nice" tick step near range/6: 1, 2 or 5 times a power of ten. */
static double tick_step(double range)
{
    double raw = range / 6.0, p = pow(10.0, floor(log10(raw))), m = raw / p;
    return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * p;
}

static void widen(double *lo, double *hi)
{
    if (!(*hi > *lo)) {
        double d = fabs(*lo) > 0.0 ? 0.1 * fabs(*lo) : 1.0;
        *lo -= d;
        *hi += d;
    }
}

/* The legend goes into the corner of the plot area that the fewest curve
 * points (and midpoints of their segments) fall into. */
#define LEGEND_W 300.0
static void legend_corner(const sbc_series *series, int nseries, double xlo, double xhi, double ylo, double yhi,
                          double *lx, double *ly)
{
    const double pw = W - LEFT - RIGHT, ph = H - TOP - BOTTOM, lh = 18.0 * nseries + 8;
    double best = DBL_MAX;
    int corner, s, k, h;
    for (corner = 0; corner < 4; ++corner) {
        const double x0 = corner % 2 ? LEFT + pw - 8 - LEGEND_W : LEFT + 8,
                     y0 = corner / 2 ? TOP + ph - 6 - lh : TOP + 6;
        double hits = 0.0;
        for (s = 0; s < nseries; ++s)
            for (k = 0; k < series[s].n; ++k)
                for (h = 0; h < 2 && (h == 0 || k + 1 < series[s].n); ++h) {
                    const double x = h ? 0.5 * (series[s].x[k] + series[s].x[k + 1]) : series[s].x[k],
                                 y = h ? 0.5 * (series[s].y[k] + series[s].y[k + 1]) : series[s].y[k],
                                 px = LEFT + (x - xlo) / (xhi - xlo) * pw, py = TOP + (yhi - y) / (yhi - ylo) * ph;
                    hits += isfinite(px) && isfinite(py) && px >= x0 - 4 && px <= x0 + LEGEND_W + 4 && py >= y0 - 4 &&
                            py <= y0 + lh + 4;
                }
        if (hits < best) { /* ties keep the earlier corner: top left, top right, bottom left, bottom right */
            best = hits;
            *lx = x0;
            *ly = y0;
        }
    }
}

sbc_status sbc_plot_svg(const char *path, const char *title, const char *xlabel, const char *ylabel, int nseries,
                        const sbc_series *series, sbc_error *err)
{
    static const char *colors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b"};
    static const char *dashes[] = {"", "8 4", "2 3", "8 3 2 3"};
    double xlo = DBL_MAX, xhi = -DBL_MAX, ylo = DBL_MAX, yhi = -DBL_MAX, step, t;
    double pw = W - LEFT - RIGHT, ph = H - TOP - BOTTOM;
    double lx = LEFT + 8, ly = TOP + 6;
    FILE *fp;
    int k, s;
    for (s = 0; s < nseries; ++s) {
        for (k = 0; k < series[s].n; ++k) {
            double x = series[s].x[k], y = series[s].y[k];
            if (!isfinite(x) || !isfinite(y)) continue;
            if (x < xlo) xlo = x;
            if (x > xhi) xhi = x;
            if (y < ylo) ylo = y;
            if (y > yhi) yhi = y;
        }
    }
    if (xlo > xhi) xlo = xhi = 0.0;
    if (ylo > yhi) ylo = yhi = 0.0;
    widen(&xlo, &xhi);
    widen(&ylo, &yhi);
    fp = sbc_output_open(path, SBC_OUTPUT_SVG, "plot", err);
    if (!fp)
        return err->status;
#define PX(v) (LEFT + ((v) - xlo) / (xhi - xlo) * pw)
#define PY(v) (TOP + (yhi - (v)) / (yhi - ylo) * ph)
    fprintf(fp, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%g\" height=\"%g\" font-family=\"sans-serif\" "
                "font-size=\"13\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n", W, H);
    fprintf(fp, "<text x=\"%g\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">%s</text>\n", W / 2, title);
    step = tick_step(xhi - xlo);
    for (t = ceil(xlo / step) * step; t <= xhi + 1e-9 * step; t += step) {
        double tv = fabs(t) < 1e-12 * step ? 0.0 : t;
        fprintf(fp, "<line x1=\"%.2f\" y1=\"%g\" x2=\"%.2f\" y2=\"%g\" stroke=\"#ddd\"/>\n", PX(t), TOP, PX(t),
                TOP + ph);
        fprintf(fp, "<text x=\"%.2f\" y=\"%g\" text-anchor=\"middle\">%g</text>\n", PX(t), TOP + ph + 18, tv);
    }
    step = tick_step(yhi - ylo);
    for (t = ceil(ylo / step) * step; t <= yhi + 1e-9 * step; t += step) {
        double tv = fabs(t) < 1e-12 * step ? 0.0 : t;
        fprintf(fp, "<line x1=\"%g\" y1=\"%.2f\" x2=\"%g\" y2=\"%.2f\" stroke=\"#ddd\"/>\n", LEFT, PY(t),
                LEFT + pw, PY(t));
        fprintf(fp, "<text x=\"%g\" y=\"%.2f\" text-anchor=\"end\">%g</text>\n", LEFT - 6, PY(t) + 4, tv);
    }
    fprintf(fp, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"none\" stroke=\"black\"/>\n", LEFT, TOP,
            pw, ph);
    fprintf(fp, "<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">%s</text>\n", LEFT + pw / 2, H - 14, xlabel);
    fprintf(fp, "<text x=\"18\" y=\"%g\" text-anchor=\"middle\" transform=\"rotate(-90 18 %g)\">%s</text>\n",
            TOP + ph / 2, TOP + ph / 2, ylabel);
    legend_corner(series, nseries, xlo, xhi, ylo, yhi, &lx, &ly);
    fprintf(fp, "<rect x=\"%g\" y=\"%g\" width=\"%g\" height=\"%g\" fill=\"white\" fill-opacity=\"0.85\" "
                "stroke=\"#999\"/>\n", lx, ly, LEGEND_W, 18.0 * nseries + 8);
    for (s = 0; s < nseries; ++s) {
        const char *c = colors[s % 6], *dash = dashes[(s / 6) % 4];
        int first = 1;
        fprintf(fp, "<polyline fill=\"none\" stroke=\"%s\" stroke-width=\"1.8\" stroke-dasharray=\"%s\" points=\"",
                c, dash);
        for (k = 0; k < series[s].n; ++k) {
            double x = series[s].x[k], y = series[s].y[k];
            if (!isfinite(x) || !isfinite(y)) continue;
            fprintf(fp, "%s%.2f,%.2f", first ? "" : " ", PX(x), PY(y));
            first = 0;
        }
        fprintf(fp, "\"/>\n");
        if (series[s].n <= SBC_PLOT_MARKERS) /* a few points: each one a dot, a single one visible at all */
            for (k = 0; k < series[s].n; ++k)
                if (isfinite(series[s].x[k]) && isfinite(series[s].y[k]))
                    fprintf(fp, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3.5\" fill=\"%s\"/>\n", PX(series[s].x[k]),
                            PY(series[s].y[k]), c);
        fprintf(fp, "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"%s\" stroke-width=\"2\" "
                    "stroke-dasharray=\"%s\"/>\n",
                lx + 6, ly + 10 + 18.0 * s, lx + 32, ly + 10 + 18.0 * s, c, dash);
        fprintf(fp, "<text x=\"%g\" y=\"%g\">%s</text>\n", lx + 38, ly + 14 + 18.0 * s, series[s].label);
    }
#undef PX
#undef PY
    fprintf(fp, "</svg>\n");
    return sbc_output_close(fp, path, "plot", err);
}
