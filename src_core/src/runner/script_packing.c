/* Runner commands on packings: generate, write_packing, rose. */
#include "script_state.h"
#include "sbc/embedded/output_file.h"

#include "sbc/frame.h"
#include "sbc/embedded/generate.h"
#include "sbc/embedded/plot.h"

#include <stdlib.h>
#include <string.h>

/* after 'dimension 3': the spheres into the script's sphere packing */
static sbc_status generate_spheres(script *s, const sbc_generate_def *def, sbc_error *err)
{
    sbc_sphere_packing p;
    sbc_generate_info info;
    sbc_status st = sbc_generate_periodic_3d(def, &p, &info, err);
    if (st != SBC_OK)
        return st;
    sbc_script_spheres_free(s);
    s->n3 = p.n;
    s->x3 = p.x;
    s->r3 = p.r;
    if (s->log)
        fprintf(s->log,
                "generate: n0 %d -> %d spheres after the periodic reconstruction; L = %.6g m, V = %.6g m^3, "
                "volume fraction %.4f, coordination %.3f, largest net force %.1e of the mean contact force\n",
                info.n0, info.n, info.L, info.L * info.L * info.L, info.fraction, info.coordination, info.residual);
    return SBC_OK;
}

/* generate periodic n0 N rmin R polydispersity PD seed S [strain E] [protocol
   shrink|pressure] (discs, or spheres after 'dimension 3') */
sbc_status sbc_script_generate(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage[] =
        "generate periodic n0 N rmin R polydispersity PD seed S [strain E] [protocol shrink|pressure]";
    sbc_generate_def def = sbc_generate_def_default();
    sbc_generate_info info;
    long n, seed;
    int k;
    sbc_status st = sbc_script_expect_count(nw > 10 && nw % 2 == 0 ? 10 : nw, w, 10, usage, err);
    if (st != SBC_OK) return st;
    for (k = 10; k + 1 < nw; k += 2) {
        if (strcmp(w[k], "strain") == 0) {
            if (sbc_parse_real(w[k + 1], "strain", &def.strain, NULL) != SBC_OK ||
                !(def.strain >= 0.0 && def.strain <= 0.05))
                return sbc_fail(err, SBC_ERR_INPUT, "generate: strain '%s' is not valid (expected a real from 0 to "
                                "0.05, the linear compression of the jammed box)", w[k + 1]);
        } else if (strcmp(w[k], "protocol") == 0) {
            if (strcmp(w[k + 1], "shrink") != 0 && strcmp(w[k + 1], "pressure") != 0)
                return sbc_fail(err, SBC_ERR_INPUT, "generate: protocol '%s' is not known (expected shrink or pressure)",
                                w[k + 1]);
            def.protocol = w[k + 1][0] == 'p' ? SBC_GENERATE_PRESSURE : SBC_GENERATE_SHRINK;
        } else {
            return sbc_fail(err, SBC_ERR_INPUT, "generate: keyword '%s' is not known (expected strain or protocol; "
                            "usage: %s)", w[k], usage);
        }
    }
    if (strcmp(w[1], "periodic") != 0)
        return sbc_fail(err, SBC_ERR_INPUT, "generate: style '%s' is not known (expected 'periodic')", w[1]);
    if ((st = sbc_script_expect_key("generate", w[2], "n0", usage, err)) != SBC_OK) return st;
    if (sbc_parse_int(w[3], "n0", 4, SBC_GENERATE_MAX, &n, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "generate: n0 '%s' is not valid (expected an integer from 4 to %d)",
                        w[3], SBC_GENERATE_MAX);
    if ((st = sbc_script_expect_key("generate", w[4], "rmin", usage, err)) != SBC_OK) return st;
    if ((st = sbc_script_positive("generate", "rmin", w[5], &def.r_min, err)) != SBC_OK) return st;
    if ((st = sbc_script_expect_key("generate", w[6], "polydispersity", usage, err)) != SBC_OK) return st;
    if (sbc_parse_real(w[7], "polydispersity", &def.polydispersity, NULL) != SBC_OK || !(def.polydispersity >= 1.0) ||
        def.polydispersity > 10.0)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "generate: polydispersity '%s' is not valid (expected a real from 1 to 10, R_max / R_min)",
                        w[7]);
    if ((st = sbc_script_expect_key("generate", w[8], "seed", usage, err)) != SBC_OK) return st;
    if (sbc_parse_int(w[9], "seed", 0, 2147483647L, &seed, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "generate: seed '%s' is not valid (expected an integer >= 0)", w[9]);
    def.n = (int)n;
    def.log = s->log;
    def.seed = (unsigned long)seed;
    if (s->bpm)
        return generate_spheres(s, &def, err);
    sbc_packing_free(&s->packing);
    s->have_packing = 0;
    if ((st = sbc_generate_periodic(&def, &s->packing, &info, err)) != SBC_OK)
        return st;
    s->have_packing = 1;
    if (s->log)
        fprintf(s->log,
                "generate: n0 %d -> %d particles after the periodic reconstruction; L = %.6g m, V = %.6g m^2, "
                "volume fraction %.4f, coordination %.3f, largest net force %.1e of the mean contact force\n",
                info.n0, info.n, info.L, info.L * info.L, info.fraction, info.coordination, info.residual);
    return SBC_OK;
}

/* The packing in one of the formats, the frame flagged where the format
 * carries it: LAMMPS and LIGGGHTS as atom type 2, YADE as a fifth column. */
sbc_status sbc_script_write_packing_as(script *s, const char *format, const char *path, sbc_error *err)
{
    sbc_status checked = sbc_script_files_check(s, path, "write_packing:", err);
    if (checked == SBC_OK && s->check)
        checked = sbc_output_probe(path, SBC_OUTPUT_PACKING, "write_packing", err);
    if (checked != SBC_OK)
        return checked;
    sbc_frame frame;
    int *is_frame, k;
    sbc_status st;
    if (strcmp(format, "text") == 0)
        return s->check ? SBC_OK : sbc_packing_write_text(&s->packing, path, err);
    if (strcmp(format, "lammps") != 0 && strcmp(format, "liggghts") != 0 && strcmp(format, "yade") != 0)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "write_packing: format '%s' is not known (expected text, lammps, liggghts or yade)", format);
    if (format[0] == 'l' && !s->have_density)
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing %s: no density (use 'density RHO' first: the data "
                                            "file carries the masses)", format);
    if ((st = sbc_frame_detect_packing(&frame, &s->packing, err)) != SBC_OK)
        return st;
    if (!(is_frame = calloc((size_t)s->packing.n, sizeof *is_frame))) {
        sbc_frame_free(&frame);
        return sbc_fail(err, SBC_ERR_NOMEM, "write_packing: out of memory");
    }
    for (k = 0; k < frame.n; ++k)
        is_frame[frame.particle[k]] = 1;
    if (s->check)
        st = SBC_OK;
    else if (strcmp(format, "lammps") == 0)
        st = sbc_packing_write_lammps(&s->packing, is_frame, s->density, path, err);
    else if (strcmp(format, "liggghts") == 0)
        st = sbc_packing_write_liggghts(&s->packing, is_frame, s->density, path, err);
    else
        st = sbc_packing_write_yade(&s->packing, is_frame, path, err);
    free(is_frame);
    sbc_frame_free(&frame);
    return st;
}

/* write_packing text|lammps|liggghts|yade FILE */
sbc_status sbc_script_write_packing(script *s, int nw, char **w, sbc_error *err)
{
    sbc_status st = sbc_script_expect_count(nw, w, 3, "write_packing text|lammps|liggghts|yade FILE", err);
    if (st != SBC_OK) return st;
    if (!s->have_packing)
        return sbc_fail(err, SBC_ERR_INPUT, "write_packing: no packing (use 'lattice', 'read_packing' or 'generate' first)");
    st = sbc_script_write_packing_as(s, w[1], w[2], err);
    if (st == SBC_OK)
        sbc_script_files_note(s, w[2], "packing written");
    return st;
}

/* rose FILE.svg: contact orientations of the packing (pairs closer than 1e-6 R_min) */
sbc_status sbc_script_rose(script *s, int nw, char **w, sbc_error *err)
{
    double *angle, rmin = 0.0;
    int n, k;
    sbc_status st = sbc_script_expect_count(nw, w, 2, "rose FILE.svg", err);
    if (st != SBC_OK) return st;
    if (!s->have_packing)
        return sbc_fail(err, SBC_ERR_INPUT, "rose: no packing (use 'lattice', 'read_packing' or 'generate' first)");
    for (k = 0; k < s->packing.n; ++k)
        if (k == 0 || s->packing.r[k] < rmin) rmin = s->packing.r[k];
    if ((st = sbc_packing_contact_angles(&s->packing, 1e-6 * rmin, &angle, &n, err)) != SBC_OK)
        return st;
    st = sbc_script_files_check(s, w[1], "rose:", err);
    if (st == SBC_OK)
        st = s->check ? sbc_output_probe(w[1], SBC_OUTPUT_SVG, "rose", err)
                      : sbc_plot_rose(w[1], "Contact orientations", n, angle, 36, err);
    free(angle);
    if (st == SBC_OK && !s->check)
        sbc_script_files_note(s, w[1], "rose diagram");
    if (st == SBC_OK && s->log)
        fprintf(s->log, "rose: %d contacts -> %s\n", n, w[1]);
    return st;
}
