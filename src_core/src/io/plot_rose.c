/* Rose diagram of contact orientations (paper Fig. 6c) as an SVG file. */
#include "sbc/embedded/plot.h"
#include "sbc/embedded/output_file.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

sbc_status sbc_plot_rose(const char *path, const char *title, int n, const double *angle, int bins, sbc_error *err)
{
    const double c = 260.0, rmax = 200.0; /* centre and radius of the largest bar, px */
    double *count, top = 0.0, w = 2.0 * M_PI / bins;
    FILE *fp;
    int k, b;
    if (bins < 4 || bins > 720 || bins % 2)
        return sbc_fail(err, SBC_ERR_INPUT, "rose: %d bins (expected an even number from 4 to 720)", bins);
    if (!(count = calloc((size_t)bins, sizeof *count)))
        return sbc_fail(err, SBC_ERR_NOMEM, "rose: out of memory");
    /* a contact normal n and -n are the same contact: count both directions */
    for (k = 0; k < n; ++k) {
        double a = fmod(angle[k], 2.0 * M_PI);
        if (!isfinite(a)) continue;
        if (a < 0.0) a += 2.0 * M_PI;
        b = (int)(a / w) % bins;
        count[b] += 1.0;
        count[(b + bins / 2) % bins] += 1.0;
    }
    for (b = 0; b < bins; ++b)
        if (count[b] > top) top = count[b];
    if (!(fp = sbc_output_open(path, SBC_OUTPUT_SVG, "rose", err))) {
        free(count);
        return err->status;
    }
    fprintf(fp, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"520\" height=\"560\" font-family=\"sans-serif\" "
                "font-size=\"13\">\n<rect width=\"100%%\" height=\"100%%\" fill=\"white\"/>\n");
    fprintf(fp, "<text x=\"260\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">%s</text>\n", title);
    for (k = 1; k <= 4; ++k)
        fprintf(fp, "<circle cx=\"%g\" cy=\"%g\" r=\"%g\" fill=\"none\" stroke=\"#ddd\"/>\n", c, c + 20, rmax * k / 4);
    for (b = 0; b < bins; ++b) {
        double r = top > 0.0 ? rmax * count[b] / top : 0.0, a0 = b * w, a1 = (b + 1) * w;
        /* SVG y grows downwards: angle a is drawn at (cos a, -sin a) */
        fprintf(fp, "<path d=\"M %g %g L %.2f %.2f A %.2f %.2f 0 0 0 %.2f %.2f Z\" fill=\"#1f77b4\" "
                    "fill-opacity=\"0.75\" stroke=\"#144c73\"/>\n",
                c, c + 20, c + r * cos(a0), c + 20 - r * sin(a0), r, r, c + r * cos(a1), c + 20 - r * sin(a1));
    }
    fprintf(fp, "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#999\"/>\n", c - rmax - 10, c + 20,
            c + rmax + 10, c + 20);
    fprintf(fp, "<line x1=\"%g\" y1=\"%g\" x2=\"%g\" y2=\"%g\" stroke=\"#999\"/>\n", c, c + 20 - rmax - 10, c,
            c + 20 + rmax + 10);
    fprintf(fp, "<text x=\"%g\" y=\"%g\">e1</text><text x=\"%g\" y=\"%g\">e2</text>\n", c + rmax + 12, c + 24, c + 4,
            c + 8 - rmax);
    fprintf(fp, "<text x=\"260\" y=\"%g\" text-anchor=\"middle\">%d contacts, %d bins of %g deg; outer ring = %g "
                "normals per bin</text>\n", 2 * c + 30, n, bins, 360.0 / bins, top);
    fprintf(fp, "</svg>\n");
    free(count);
    return sbc_output_close(fp, path, "rose", err);
}
