#include "layer.h"

#include <string.h>

#include "sbc/embedded/generate.h"

sbc_engine *test_layer(sbc_packing *p, sbc_frame *f, int fire)
{
    sbc_generate_def g = sbc_generate_def_default();
    sbc_engine_def d = sbc_engine_def_default();
    sbc_error err;
    sbc_engine *e;
    g.n = 25;
    g.r_min = 0.8e-3;
    g.polydispersity = 1.5;
    if (sbc_generate_periodic(&g, p, NULL, &err) != SBC_OK)
        return NULL;
    if (sbc_frame_detect_packing(f, p, &err) != SBC_OK) {
        sbc_packing_free(p);
        return NULL;
    }
    d.n = p->n;
    d.x = p->x;
    d.r = p->r;
    d.density = 1e4;
    d.law.kn = LAYER_KN;
    d.law.ks = 4e7;
    d.law.mu = 0.6;
    d.dt = LAYER_DT;
    d.fire = fire;
    d.alpha = d.beta = fire ? 0.0 : 0.7;
    if (!(e = sbc_engine_create(&d, &err))) {
        sbc_frame_free(f);
        sbc_packing_free(p);
        return NULL;
    }
    sbc_engine_set_frame(e, f);
    return e;
}

void test_square_lattice(int N, double d, double R, double *xy, double *r)
{
    int i, j;
    for (j = 0; j < N; ++j)
        for (i = 0; i < N; ++i) {
            xy[2 * (N * j + i)] = d * i;
            xy[2 * (N * j + i) + 1] = d * j;
            r[N * j + i] = R;
        }
}

int test_seal_chain(double *xy, double *r)
{
    static const double chain_y[4] = {0.52e-3, 2.52e-3, 4.52e-3, 6.27e-3};
    int i, j, n = 0;
    for (j = 0; j < 5; ++j)
        for (i = 0; i < 5; ++i)
            if (i != 2 || j == 4) {
                xy[2 * n] = 2e-3 * i;
                xy[2 * n + 1] = 2e-3 * j;
                r[n++] = 1e-3;
            }
    for (j = 0; j < 4; ++j) {
        xy[2 * n] = 4e-3;
        xy[2 * n + 1] = chain_y[j];
        r[n++] = j < 3 ? 1e-3 : 0.75e-3;
    }
    return n;
}

static void idle_interior(void *u, const sbc_fire_mix *m, int again, double out[2])
{
    (void)u, (void)m, (void)again;
    out[0] = out[1] = 0.0;
}
static void idle_contacts(void *u, double out[4])
{
    (void)u;
    out[0] = out[1] = out[2] = out[3] = 0.0;
}
static void idle_frame(void *u, double *buf) { (void)u, (void)buf; }
static void idle_fire_sums(void *u, double *sums) { (void)u, (void)sums; }

int test_driver_refused(const sbc_settings *s, sbc_error *err)
{
    double xy[2 * 25], rad[25], mass[25];
    sbc_packing pk;
    sbc_frame f;
    sbc_controller *c;
    sbc_driver_callbacks cb;
    sbc_driver *d = NULL;
    int k;
    test_square_lattice(5, 2e-3, 1.01e-3, xy, rad);
    memset(&pk, 0, sizeof pk);
    pk.n = 25;
    pk.x = xy;
    pk.r = rad;
    for (k = 0; k < 25; ++k)
        mass[k] = 1e-5;
    if (sbc_frame_detect_packing(&f, &pk, err) != SBC_OK)
        return 0;
    if ((c = sbc_controller_create(&f, s, mass, 1e-5, 1e4, err))) {
        memset(&cb, 0, sizeof cb);
        cb.interior = idle_interior;
        cb.contacts = idle_contacts;
        cb.frame = idle_frame;
        cb.fire_sums = idle_fire_sums;
        d = sbc_driver_create(c, s, &cb, err);
    }
    sbc_driver_free(d);
    sbc_controller_free(c);
    sbc_frame_free(&f);
    return c && !d;
}
