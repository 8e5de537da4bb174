/* Contact network picture (Figs. 8 and 12) as a self-contained SVG file. */
#include "sbc/embedded/network.h"
#include "sbc/confine.h"
#include "sbc/embedded/output_file.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define WIDTH 640.0 /* px of the packing's extent along x */
#define MARGIN 20.0 /* px */
#define TOP 60.0    /* px of title and legend above the picture */

/* 1 for the interior discs whose centre is outside the frame's polygon, into
 * out [n] (zeroed when there is no frame); their count */
static int outside_frame(const sbc_engine_view *w, const sbc_frame *frame, double *fx, unsigned char *out)
{
    sbc_confine c;
    int k, count = 0;
    for (k = 0; k < w->n; ++k) out[k] = 0;
    if (!frame) return 0;
    sbc_frame_centres(frame, w->x, fx);
    sbc_confine_prepare(&c, frame, fx);
    for (k = 0; k < w->n; ++k)
        if (!w->kinematic[k] && !sbc_confine_inside(&c, &w->x[2 * k])) count += out[k] = 1;
    return count;
}

sbc_status sbc_network_svg(const char *path, const char *title, const sbc_engine_view *w, const sbc_frame *frame,
                           sbc_error *err)
{
    double lo[2] = {DBL_MAX, DBL_MAX}, hi[2] = {-DBL_MAX, -DBL_MAX}, s, fmax = 0.0, height, *fx;
    int k, contacts = 0, bonds = 0, outside;
    unsigned char *out;
    FILE *fp;
    for (k = 0; k < w->n; ++k) {
        int a;
        for (a = 0; a < 2; ++a) {
            if (w->x[2 * k + a] - w->r[k] < lo[a]) lo[a] = w->x[2 * k + a] - w->r[k];
            if (w->x[2 * k + a] + w->r[k] > hi[a]) hi[a] = w->x[2 * k + a] + w->r[k];
        }
    }
    if (w->n < 1 || !(hi[0] > lo[0]) || !(hi[1] > lo[1]) || !isfinite(hi[0] - lo[0]) || !isfinite(hi[1] - lo[1]))
        return sbc_fail(err, SBC_ERR_INPUT, "network: no particles or a non-finite extent");
    s = WIDTH / (hi[0] - lo[0]); /* px per m */
    height = (hi[1] - lo[1]) * s;
    /* |fn| = kn |dn| of every force-carrying pair (eqs. 6-7), for the line widths */
    for (k = 0; k < w->pair_count; ++k) {
        int i = w->pair_i[k], j = w->pair_j[k], b = w->pair_bond && w->pair_bond[k];
        double dn = w->r[i] + w->r[j] - hypot(w->x[2 * j] - w->x[2 * i], w->x[2 * j + 1] - w->x[2 * i + 1]);
        if (dn > 0.0 || b) {
            if (fabs(w->law.kn * dn) > fmax) fmax = fabs(w->law.kn * dn);
            bonds += b;
            contacts += !b;
        }
    }
    fx = malloc(sizeof *fx * 3 * (size_t)(frame ? frame->n : 1));
    out = malloc((size_t)w->n);
    if (!fx || !out) {
        free(fx);
        free(out);
        return sbc_fail(err, SBC_ERR_NOMEM, "network: out of memory for %d particles", w->n);
    }
    outside = outside_frame(w, frame, fx, out);
    if (!(fp = sbc_output_open(path, SBC_OUTPUT_SVG, "network", err))) {
        free(fx);
        free(out);
        return err->status;
    }
    fprintf(fp, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" font-family=\"sans-serif\" "
                "font-size=\"13\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n",
            WIDTH + 2 * MARGIN, height + TOP + MARGIN + (frame ? 20.0 : 0.0));
    fprintf(fp, "<text x=\"%g\" y=\"22\" text-anchor=\"middle\" font-size=\"15\">%s</text>\n", 0.5 * WIDTH + MARGIN,
            title);
    fprintf(fp, "<text x=\"%g\" y=\"44\" text-anchor=\"middle\"><tspan fill=\"#1f4fd8\">%d frictional contacts"
                "</tspan>, <tspan fill=\"#d62728\">%d cohesive bonds</tspan>; line width ~ |fn|, max %.4g N; "
                "t = %.6g s</text>\n",
            0.5 * WIDTH + MARGIN, contacts, bonds, fmax, w->time);
    /* SVG y grows downwards: y_px = TOP + (hi_y - y) s */
#define PX(v) (MARGIN + ((v) - lo[0]) * s)
#define PY(v) (TOP + (hi[1] - (v)) * s)
    for (k = 0; k < w->n; ++k)
        fprintf(fp, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.2f\" fill=\"%s\" stroke=\"#999\" stroke-width=\"0.6\"/>\n",
                PX(w->x[2 * k]), PY(w->x[2 * k + 1]), w->r[k] * s,
                out[k] ? "#ff9900" : w->kinematic[k] ? "#e4e4e4" : "none");
    if (frame) {
        int q;
        fprintf(fp, "<polygon fill=\"none\" stroke=\"#222\" stroke-width=\"1\" points=\"");
        for (q = 0; q < frame->n; ++q) fprintf(fp, "%s%.2f,%.2f", q ? " " : "", PX(fx[3 * q]), PY(fx[3 * q + 1]));
        fprintf(fp, "\"/>\n");
        fprintf(fp, "<text x=\"%g\" y=\"%g\" text-anchor=\"middle\">black: the polygon of the frame's centres; "
                    "<tspan fill=\"#ff9900\">discs outside it: %d</tspan></text>\n",
                0.5 * WIDTH + MARGIN, height + TOP + 0.75 * MARGIN + 14.0, outside);
    }
    for (k = 0; k < w->pair_count; ++k) {
        int i = w->pair_i[k], j = w->pair_j[k], b = w->pair_bond && w->pair_bond[k];
        double dn = w->r[i] + w->r[j] - hypot(w->x[2 * j] - w->x[2 * i], w->x[2 * j + 1] - w->x[2 * i + 1]);
        double width = fmax > 0.0 ? 0.4 + 4.0 * fabs(w->law.kn * dn) / fmax : 0.4;
        if (!(dn > 0.0 || b)) continue;
        fprintf(fp, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" stroke=\"%s\" stroke-width=\"%.2f\"%s/>\n",
                PX(w->x[2 * i]), PY(w->x[2 * i + 1]), PX(w->x[2 * j]), PY(w->x[2 * j + 1]), b ? "#d62728" : "#1f4fd8",
                width, b && dn < 0.0 ? " stroke-dasharray=\"3 2\"" : "");
    }
#undef PX
#undef PY
    fprintf(fp, "</svg>\n");
    free(fx);
    free(out);
    return sbc_output_close(fp, path, "network", err);
}
