#include "layer.h"

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
