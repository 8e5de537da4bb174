/* The frame's seal (seal.h): the wall force and its split against closed
 * forms, forces as the gradient of the wall energy, the Verlet list, and a
 * disc that bounces off a wall in the engine without losing energy. */
#include "check.h"
#include "csv_read.h"
#include "layer.h"
#include "tests.h"

#include "sbc/embedded/engine.h"
#include "sbc/host.h"
#include "sbc/embedded/script.h"
#include "sbc/seal.h"
#include "sbc/settings.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* a square frame of side L, corners in frame order (counter-clockwise when ccw) */
typedef struct {
    sbc_frame f;
    int particle[4], side[4], partner[4];
    double X[12], R[4], A[12];
} square;

static void square_make(square *s, double L, int ccw)
{
    static const double unit[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    int q;
    memset(s, 0, sizeof *s);
    for (q = 0; q < 4; ++q) {
        int src = ccw ? q : (4 - q) % 4;
        s->particle[q] = q;
        s->partner[q] = -1;
        s->X[3 * q] = L * unit[2 * src];
        s->X[3 * q + 1] = L * unit[2 * src + 1];
        s->R[q] = 0.1 * L;
        s->f.corner[q] = q;
    }
    s->f.dim = 2;
    s->f.n = 4;
    s->f.particle = s->particle;
    s->f.side = s->side;
    s->f.partner = s->partner;
    s->f.X = s->X;
    s->f.R = s->R;
    s->f.A = s->A;
    s->f.V = L * L;
}

static int never_frame(const void *ctx, int k) { (void)ctx; (void)k; return -1; }

/* one interior disc at x [2] with radius *r, its force into f [2] */
static sbc_seal_particles one_disc(const double *x, double *f, const double *r)
{
    sbc_seal_particles pt;
    pt.n = 1;
    pt.x = x;
    pt.f = f;
    pt.stride = 2;
    pt.r = r;
    pt.frame = never_frame;
    pt.ctx = NULL;
    return pt;
}

/* wall energy and forces of one disc at p against the frame's centres fx */
static double wall(const sbc_frame *f, const double *fx, const double p[2], double r, double kn, double force[2],
                   double reaction[12])
{
    sbc_seal s;
    sbc_seal_particles pt;
    sbc_error err;
    double e = -1.0;
    force[0] = force[1] = 0.0;
    memset(reaction, 0, sizeof(double) * 12);
    pt = one_disc(p, force, &r);
    if (sbc_seal_init(&s, f, 0.25 * r, &err) == SBC_OK)
        sbc_seal_forces(&s, f, fx, &pt, kn, 1, reaction, &e, &err);
    sbc_seal_free(&s);
    return e;
}

static void closed_form(void)
{
    const double L = 1.0, r = 0.05, kn = 1e4, wall_at = SBC_SEAL_WALL * r;
    square sq;
    int ccw;
    for (ccw = 0; ccw < 2; ++ccw) {
        double p[2], f[2], R[12], e, s = 0.3 * wall_at, t = 0.25, t_ab, fn = kn * (wall_at - s), sum[2] = {0, 0}, moment = 0.0;
        int a = ccw ? 0 : 3, b = ccw ? 1 : 0, q; /* the bottom edge runs 0 -> 1 (ccw) or 3 -> 0 (cw) */
        square_make(&sq, L, ccw);
        p[0] = t * L;
        p[1] = s;
        e = wall(&sq.f, sq.X, p, r, kn, f, R);
        CHECK_ABS(f[0], 0.0, 1e-12);
        CHECK_REL(f[1], fn, 1e-12); /* inwards: +y, whatever the frame order */
        CHECK_REL(e, 0.5 * fn * (wall_at - s), 1e-12);
        /* the lever rule: of the edge a -> b, a takes 1 - t_ab; the corner at x = 0 is the nearer */
        t_ab = ccw ? t : 1.0 - t;
        CHECK_REL(R[3 * a + 1], -(1.0 - t_ab) * fn, 1e-12);
        CHECK_REL(R[3 * b + 1], -t_ab * fn, 1e-12);
        for (q = 0; q < 4; ++q) {
            sum[0] += R[3 * q];
            sum[1] += R[3 * q + 1];
            moment += sq.X[3 * q] * R[3 * q + 1] - sq.X[3 * q + 1] * R[3 * q];
        }
        /* action and reaction: no net force and no net moment about the origin */
        CHECK_ABS(sum[0] + f[0], 0.0, 1e-12 * fn);
        CHECK_ABS(sum[1] + f[1], 0.0, 1e-12 * fn);
        CHECK_ABS(moment + (p[0] * f[1] - p[1] * f[0]), 0.0, 1e-12 * fn * L);
        /* beyond the wall, and off the segment's span: nothing */
        p[1] = 1.01 * wall_at;
        CHECK(wall(&sq.f, sq.X, p, r, kn, f, R) == 0.0 && f[1] == 0.0 && R[3 * a + 1] == 0.0);
        /* the walls end at the frame's centres: off both spans at a corner, nothing either */
        p[0] = -0.6 * r;
        p[1] = -0.2 * r;
        CHECK(wall(&sq.f, sq.X, p, r, kn, f, R) == 0.0 && f[0] == 0.0 && f[1] == 0.0);
        /* a disc whose centre has crossed the line within the span is pushed back in */
        p[0] = 0.5 * L;
        p[1] = -0.2 * r;
        wall(&sq.f, sq.X, p, r, kn, f, R);
        CHECK_REL(f[1], kn * (wall_at + 0.2 * r), 1e-12);
    }
}

/* the forces are minus the gradient of the wall energy in every coordinate,
 * the frame's centres included: the split does the work of the wall force */
static void energy_gradient(void)
{
    const double L = 1.0, r = 0.05, kn = 1e4, h = 1e-7;
    const double fx0[12] = {0.01, -0.02, 0.0, 1.03, 0.04, 0.0, 0.98, 1.02, 0.0, -0.01, 0.97, 0.0};
    const double p0[2] = {0.63, 0.03}; /* near the tilted bottom edge */
    square sq;
    double f[2], R[12], fp[2], Rp[12], e0;
    int c;
    square_make(&sq, L, 1);
    e0 = wall(&sq.f, fx0, p0, r, kn, f, R);
    CHECK(e0 > 0.0 && f[1] > 0.0);
    for (c = 0; c < 10; ++c) {
        const int slot = c < 2 ? 0 : 3 * ((c - 2) / 2) + (c - 2) % 2; /* of the frame's coordinate c - 2 */
        double fx[12], p[2], ep, em, grad;
        memcpy(fx, fx0, sizeof fx);
        memcpy(p, p0, sizeof p);
        if (c < 2) p[c] += h; else fx[slot] += h;
        ep = wall(&sq.f, fx, p, r, kn, fp, Rp);
        memcpy(fx, fx0, sizeof fx);
        memcpy(p, p0, sizeof p);
        if (c < 2) p[c] -= h; else fx[slot] -= h;
        em = wall(&sq.f, fx, p, r, kn, fp, Rp);
        grad = (ep - em) / (2.0 * h);
        CHECK_ABS(c < 2 ? f[c] : R[slot], -grad, 1e-6 * kn * r);
    }
}

/* the Verlet list: a disc that comes from far off the wall is collected in
 * time, and its force is that of a fresh collection at every step */
static void verlet(void)
{
    const double r = 0.05, kn = 1e4;
    square sq;
    sbc_seal s;
    sbc_seal_particles pt;
    sbc_error err;
    double x[2] = {0.5, 0.5}, f[2], R[12], e, fresh[2], Rf[12];
    int k, met = 0, same = 1;
    square_make(&sq, 1.0, 1);
    pt = one_disc(x, f, &r);
    CHECK(sbc_seal_init(&s, &sq.f, 0.25 * r, &err) == SBC_OK);
    for (k = 0; k < 1000; ++k) {
        x[1] = 0.5 - 0.5 * k / 999.0; /* down to the bottom edge, in steps of 0.01 r */
        f[0] = f[1] = 0.0;
        memset(R, 0, sizeof R);
        if (sbc_seal_forces(&s, &sq.f, sq.X, &pt, kn, 0, R, &e, &err) != SBC_OK)
            same = 0;
        wall(&sq.f, sq.X, x, r, kn, fresh, Rf);
        same &= f[1] == fresh[1] && R[1] == Rf[1];
        met |= f[1] > 0.0;
    }
    CHECK(met);
    CHECK(same);
    sbc_seal_free(&s);
}

/* The engine: a disc at rest, pressed into the bottom wall between two far
 * apart frame discs, leaves it with the speed of the wall's spring energy
 * (no damping); the frame takes the reactions meanwhile. Without the seal it
 * stays where it is. */
static void engine_bounce(void)
{
    const double L = 1.0, r = 0.05, kn = 1e4, rho = 2e3, s0 = 0.2 * SBC_SEAL_WALL * r;
    const double m = rho * M_PI * r * r, delta = SBC_SEAL_WALL * r - s0;
    double x[10], rad[5], v_out = 0.0, reaction_max = 0.0;
    square sq;
    sbc_engine_def d = sbc_engine_def_default();
    sbc_engine *e;
    sbc_error err;
    int k, q, sealed;
    square_make(&sq, L, 1);
    for (q = 0; q < 4; ++q) { /* host centres [2n] */
        x[2 * q] = sq.X[3 * q];
        x[2 * q + 1] = sq.X[3 * q + 1];
    }
    for (q = 0; q < 4; ++q)
        rad[q] = 0.1 * r; /* small frame discs: the disc touches only the wall */
    x[8] = 0.4 * L;
    x[9] = s0;
    rad[4] = r;
    d.n = 5;
    d.x = x;
    d.r = rad;
    d.density = rho;
    d.law.kn = kn;
    d.law.ks = 0.0;
    d.law.mu = 0.0;
    d.alpha = d.beta = 0.0;
    d.dt = 1e-3 * sqrt(m / kn);
    for (sealed = 0; sealed < 2; ++sealed) {
        if (!(e = sbc_engine_create(&d, &err))) {
            CHECK(0);
            return;
        }
        sbc_engine_set_frame(e, &sq.f);
        CHECK(!sealed || sbc_engine_seal(e, &err) == SBC_OK);
        for (k = 0; k < 4000; ++k) { /* the contact lasts pi/2 sqrt(m/kn): 1571 steps */
            sbc_engine_view w;
            if (sbc_engine_step(e, &err) != SBC_OK) {
                CHECK(0);
                break;
            }
            w = sbc_engine_get_view(e);
            if (k == 0) {
                CHECK_ABS(w.f[9], sealed ? kn * delta : 0.0, 1e-9 * kn * delta);
                reaction_max = -(w.f[1] + w.f[3]); /* the bottom corners' reactions */
            }
            sbc_engine_move_frame(e, NULL);
            v_out = w.v[9];
        }
        if (sealed) {
            CHECK_REL(reaction_max, kn * delta, 1e-12);
            CHECK_REL(v_out, delta * sqrt(kn / m), 2e-3); /* 1/2 m v^2 = 1/2 kn delta^2 */
        } else {
            CHECK(v_out == 0.0);
        }
        sbc_engine_free(e);
    }
}

/* A 5 x 5 lattice (spacing 2 mm, radius 1 mm, frictional) whose bottom
 * middle frame disc is missing: the middle column is a chain standing on the
 * wall of the gap, three discs at y = 0.52, 2.52, 4.52 mm and one of radius
 * 0.75 mm at 6.27 mm that touches the top frame disc 0.02 mm deep. Under (D)
 * F22 = 0.99 the chain closes its 0.02 mm to the wall and shares the top's
 * 0.08 mm with its 5 springs in series: 0.16 N, beside the 0.2 N of each
 * other column (two interior, two frame). sigma22 = -(4 x 0.2 + 0.16) N /
 * 8 mm = -120 N/m; -100 N/m without the seal, where the chain falls into the
 * gap. Through a file of the runner, in `make check` on every host too
 * (inputs/compare/seal_chain_D.sbc). */
static void chain(void)
{
    static double rows[4][CSV_COLS];
    char csv[512], packing[512], script[2048], line[128], text[4096] = "";
    double xy[2 * 28], r[28];
    sbc_error err;
    int k, n = test_seal_chain(xy, r), sealed;
    for (k = 0; k < n; ++k) {
        snprintf(line, sizeof line, "%.17g %.17g %.17g\n", xy[2 * k], xy[2 * k + 1], r[k]);
        strcat(text, line);
    }
    snprintf(packing, sizeof packing, "%s/seal_chain.txt", test_tmpdir);
    CHECK(write_text(packing, text) == 0);
    for (sealed = 0; sealed < 2; ++sealed) {
        snprintf(csv, sizeof csv, "%s/seal_chain_%d.csv", test_tmpdir, sealed);
        snprintf(script, sizeof script,
                 "dimension 2\nread_packing %s\ncontact frictional kn 1e4 ks 2e3 mu 0.4\ndensity 2e3\n"
                 "timestep 1e-5\nservo_bc D F 1 0 0 0.99 increments 2 accuracy tight seal %s file %s\nrun\n",
                 packing, sealed ? "yes" : "no", csv);
        CHECK(sbc_script_run_string(script, "seal_chain", NULL, &err) == SBC_OK);
        if (csv_read(csv, rows, 4) != 3) {
            CHECK(0);
            continue;
        }
        CHECK_REL(rows[2][COL("sigma22")], sealed ? -(4 * 0.2 + 0.16) / 8e-3 : -0.8 / 8e-3, 1e-7);
        CHECK_ABS(rows[2][COL("sigma11")], 0.0, 1e-7 * 120.0);
        CHECK_ABS(rows[2][COL("sigma12")], 0.0, 1e-7 * 120.0);
    }
}

/* the keyword: yes, no, and what else is refused with its name */
static void keyword(void)
{
    static const char *const yes[] = {"T", "seal", "yes"}, *const no[] = {"T", "seal", "yes", "seal", "no"};
    static const char *const bad[] = {"T", "seal", "maybe"}, *const missing[] = {"T", "seal"};
    sbc_settings s;
    sbc_error err;
    CHECK(sbc_settings_parse(&s, 3, yes, &err) == SBC_OK && s.seal == 1);
    CHECK(sbc_settings_parse(&s, 2, yes, &err) == SBC_ERR_INPUT && strstr(err.message, "keyword 'seal': missing yes|no"));
    CHECK(sbc_settings_parse(&s, 1, yes, &err) == SBC_OK && s.seal == 0); /* off by default */
    CHECK(sbc_settings_parse(&s, 3, bad, &err) == SBC_ERR_INPUT &&
          strstr(err.message, "keyword 'seal': value 'maybe' is not valid (expected yes or no)"));
    CHECK(sbc_settings_parse(&s, 2, missing, &err) == SBC_ERR_INPUT);
    /* given twice: refused as every keyword is */
    CHECK(sbc_settings_parse(&s, 5, no, &err) == SBC_ERR_INPUT && strstr(err.message, "seal"));
}

/* The host handle (YADE's way in): the walls' forces for all particles at
 * once, reactions on the frame particles included. A 5 x 5 lattice without
 * the bottom middle disc, the disc above the gap lowered to s = 0.3 r over
 * the line of the bottom frame centres: kn (r/2 - 0.3 r) upwards on it, half
 * of it downwards on each frame disc beside the gap; none before it is
 * lowered; none without the keyword. */
static void host_handle(void)
{
    const double r = 1e-3, kn = 1e4, m = 2e3 * M_PI * r * r;
    double xy[48], rad[24], mass[24], f[48], e;
    int i, j, n = 0, gap = -1, left = -1, right = -1, sealed, list[1] = {0};
    char msg[256];
    for (j = 0; j < 5; ++j)
        for (i = 0; i < 5; ++i) {
            if (i == 2 && j == 0)
                continue;
            if (i == 2 && j == 1) gap = n;
            if (i == 1 && j == 0) left = n;
            if (i == 3 && j == 0) right = n;
            xy[2 * n] = 2e-3 * i;
            xy[2 * n + 1] = 2e-3 * j;
            rad[n] = r;
            mass[n] = m;
            ++n;
        }
    for (sealed = 0; sealed < 2; ++sealed) {
        sbc_host *h = sbc_host_create(sealed ? "D F 1 0 0 0.99 seal yes" : "D F 1 0 0 0.99", 2, n, xy, rad, mass, 0, list,
                                      1e-5, kn, msg, sizeof msg);
        CHECK(h != NULL);
        if (!h)
            continue;
        CHECK(sbc_host_sealed(h) == sealed);
        CHECK(sbc_host_seal(h, xy, f, &e) == 0 && f[2 * gap + 1] == 0.0 && e == 0.0);
        xy[2 * gap + 1] = 0.3 * r;
        CHECK(sbc_host_seal(h, xy, f, &e) == sealed);
        CHECK_REL(f[2 * gap + 1], sealed ? kn * 0.2 * r : 0.0, 1e-12);
        CHECK_REL(f[2 * left + 1], sealed ? -0.5 * kn * 0.2 * r : 0.0, 1e-12);
        CHECK_REL(f[2 * right + 1], sealed ? -0.5 * kn * 0.2 * r : 0.0, 1e-12);
        CHECK_REL(e, sealed ? 0.5 * kn * 0.04 * r * r : 0.0, 1e-12);
        xy[2 * gap + 1] = 2e-3;
        sbc_host_free(h);
    }
}

void test_seal(void)
{
    host_handle();
    keyword();
    closed_form();
    energy_gradient();
    verlet();
    engine_bounce();
    chain();
}
