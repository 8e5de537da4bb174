/* servo_bc: a line chart as a self-contained SVG file (no dependencies). */
#ifndef SBC_PLOT_H
#define SBC_PLOT_H

#include "sbc/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sbc_series {
    const char *label;
    int n;           /* points */
    const double *x; /* [n] */
    const double *y; /* [n] */
} sbc_series;

/* A series of at most this many points gets a dot at every point. */
#define SBC_PLOT_MARKERS 25

/* Writes an SVG chart of the series, with axis labels, ticks and a legend.
 * Non-finite points are skipped. */
sbc_status sbc_plot_svg(const char *path, const char *title, const char *xlabel, const char *ylabel, int nseries,
                        const sbc_series *series, sbc_error *err);

/* Rose diagram of contact orientations (paper Fig. 6c): angle[k] (rad) of
 * each contact normal, counted with its opposite direction, in `bins` equal
 * sectors (even, 4 to 720); bar length proportional to the count. */
sbc_status sbc_plot_rose(const char *path, const char *title, int n, const double *angle, int bins, sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
