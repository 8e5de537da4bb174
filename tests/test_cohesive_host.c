/* The 2D contact laws with cohesive bonds behind a host's own integrator
 * (cohesive_host.h), as fix servo_bc/bonds cohesive and servo_bc.Cohesive
 * use them: one bond in tension, in failure and in bending against eqs. 7-8
 * by hand; a bonded packing integrated here through the host path against
 * the embedded engine integrating the same packing itself; the state round
 * trip of a restart; the refusals. */
#include "check.h"
#include "tests.h"

#include "sbc/cohesive_host.h"
#include "sbc/embedded/engine.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Table 6 in SI */
static const char *TABLE6 = "kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6";
static const double KN = 1e8, KS = 4e7, KR = 20, FN = 300, R = 1e-3;

static void one_bond(void)
{
    const double x[4] = {0, 0, 2 * R, 0}, r[2] = {R, R}, dt = 1e-6;
    double xy[4], v[4] = {0}, w[2] = {0}, load[6], sums[4];
    char msg[256];
    sbc_cohesive_host *h = sbc_cohesive_host_create(TABLE6, 2, x, r, msg, sizeof msg);
    CHECK(h != NULL);
    if (!h)
        return;
    CHECK(sbc_cohesive_host_bond_count(h) == 1);
    CHECK_REL(sbc_cohesive_host_kn(h), KN, 0);
    /* eq. 7: stretched by d < fn_u / kn, the bond pulls with kn d */
    {
        const double d = 1e-6;
        memcpy(xy, x, sizeof xy);
        xy[2] += d;
        v[2] = d / dt;
        CHECK(sbc_cohesive_host_loads(h, xy, v, w, dt, load) == 0);
        CHECK_REL(load[0], KN * d, 1e-9);  /* i pulled towards j */
        CHECK_REL(load[3], -KN * d, 1e-9); /* j pulled back */
        CHECK_ABS(load[1] + load[4] + load[2] + load[5], 0.0, 1e-12);
        sbc_cohesive_host_sums(h, sums);
        CHECK_REL(sums[0], 0.5 * KN * d * d, 1e-6); /* eq. 12 */
        CHECK_ABS(sums[2], 1.0, 0);
        CHECK(sbc_cohesive_host_bond_count(h) == 1);
    }
    /* eq. 8 alone in tension: kn d >= fn_u breaks it; apart, nothing acts */
    {
        const double d = 1.01 * FN / KN;
        xy[2] = x[2] + d;
        v[2] = (1.01 * FN / KN - 1e-6) / dt;
        CHECK(sbc_cohesive_host_loads(h, xy, v, w, dt, load) == 0);
        CHECK(sbc_cohesive_host_bond_count(h) == 0);
        CHECK_ABS(load[0], 0.0, 0);
        CHECK_ABS(load[3], 0.0, 0);
    }
    sbc_cohesive_host_free(h);
    /* bending: j turned by dtheta in one step. dus = -R_j dtheta, so
     * fs = -ks R dtheta (eq. 7); the bond moment kr dtheta acts +m on i and
     * -m on j (contact.h); the moments are R fs + m on i, R fs - m on j */
    h = sbc_cohesive_host_create(TABLE6, 2, x, r, msg, sizeof msg);
    CHECK(h != NULL);
    if (!h)
        return;
    {
        const double dth = 1e-4, fs = -KS * R * dth, m = KR * dth;
        double w1[2] = {0, dth / dt}, v0[4] = {0};
        CHECK(sbc_cohesive_host_loads(h, x, v0, w1, dt, load) == 0);
        CHECK_REL(load[2], R * fs + m, 1e-9);
        CHECK_REL(load[5], R * fs - m, 1e-9);
        /* force on i: fs t with t = (0, 1) */
        CHECK_REL(load[1], fs, 1e-9);
        CHECK_REL(load[4], -fs, 1e-9);
        CHECK(sbc_cohesive_host_bond_count(h) == 1); /* criterion |fs|/fs_u + |m|/m_u = 0.067 + 0.01 */
    }
    sbc_cohesive_host_free(h);
}

/* a 6 x 6 lattice (spacing 2R, so all 60 neighbours bond) whose centres are
 * perturbed by up to 2e-3 R, under no damping: the host path integrated here
 * with the embedded engine's update (v += dt f / M, x += dt v) against the
 * engine integrating it. The largest centre difference after STEPS steps, m. */
#define SIDE 6
#define NDISC (SIDE * SIDE)

/* one step of the embedded engine's update with the loads [3 NDISC]: its
 * masses (rho pi R^2) and its multiplications by their inverses */
static void advance(double *xy, double *v, double *w, const double *load, double rho, double dt)
{
    const double M = rho * 3.14159265358979323846 * R * R, inv_m = 1.0 / M, inv_I = 1.0 / (0.5 * M * R * R);
    int k;
    for (k = 0; k < NDISC; ++k) {
        v[2 * k] += dt * load[3 * k] * inv_m;
        v[2 * k + 1] += dt * load[3 * k + 1] * inv_m;
        w[k] += dt * load[3 * k + 2] * inv_I;
        xy[2 * k] += dt * v[2 * k];
        xy[2 * k + 1] += dt * v[2 * k + 1];
    }
}
static double against_engine(int steps, int restart_at)
{
    double x0[2 * NDISC], r[NDISC], xy[2 * NDISC], v[2 * NDISC] = {0}, w[NDISC] = {0}, load[3 * NDISC];
    const double rho = 2e3, dt = 2e-7;
    sbc_engine_def def = sbc_engine_def_default();
    sbc_engine *e;
    sbc_cohesive_host *h;
    sbc_cohesive law = {1e8, 4e7, 20, 300, 60, 0.2, 0.6};
    sbc_error err;
    char msg[256];
    double worst = 0.0;
    /* the distributed path of fix servo_bc/bonds cohesive: the same packing
     * pair by pair (sbc_cohesive_pairs_step), each pair's state kept here */
    static double state[NDISC][NDISC][SBC_COHESIVE_PAIR_STATE];
    double xp[2 * NDISC], vp[2 * NDISC] = {0}, wp[NDISC] = {0}, lp[3 * NDISC], sums_p[4], sums_h[4];
    unsigned seed = 12345u;
    int k, s, i, j, intact_p = 0;
    for (k = 0; k < NDISC; ++k) {
        seed = seed * 1103515245u + 12345u;
        x0[2 * k] = 2 * R * (k % SIDE) + 2e-3 * R * ((double)(seed >> 8 & 0xffff) / 65535.0 - 0.5);
        seed = seed * 1103515245u + 12345u;
        x0[2 * k + 1] = 2 * R * (k / SIDE) + 2e-3 * R * ((double)(seed >> 8 & 0xffff) / 65535.0 - 0.5);
        r[k] = R;
    }
    def.n = NDISC;
    def.x = x0;
    def.r = r;
    def.density = rho;
    def.bonds = &law;
    def.law.kn = law.kn;
    def.dt = dt;
    def.alpha = def.beta = 0.0;
    e = sbc_engine_create(&def, &err);
    h = sbc_cohesive_host_create(TABLE6, NDISC, x0, r, msg, sizeof msg);
    CHECK(e != NULL && h != NULL);
    if (!e || !h) {
        sbc_engine_free(e);
        sbc_cohesive_host_free(h);
        return HUGE_VAL;
    }
    CHECK(sbc_cohesive_host_bond_count(h) == sbc_engine_get_view(e).bond_count);
    memcpy(xy, x0, sizeof xy);
    memcpy(xp, x0, sizeof xp);
    for (i = 0; i < NDISC; ++i)
        for (j = i + 1; j < NDISC; ++j)
            intact_p += sbc_cohesive_pair_start(&x0[2 * i], r[i], &x0[2 * j], r[j], R, state[i][j]);
    CHECK(intact_p == sbc_engine_get_view(e).bond_count);
    for (s = 0; s < steps; ++s) {
        if (s == restart_at) { /* a restart: a new host at the present centres, given the saved state */
            size_t size = sbc_cohesive_host_state_size(h);
            double *state = malloc(sizeof(double) * size);
            sbc_cohesive_host *again = sbc_cohesive_host_create(TABLE6, NDISC, xy, r, msg, sizeof msg);
            CHECK(state != NULL && again != NULL);
            if (!state || !again) {
                free(state);
                sbc_cohesive_host_free(again);
                break;
            }
            sbc_cohesive_host_state_get(h, state);
            CHECK(sbc_cohesive_host_state_set(again, state, size) == 0);
            CHECK(sbc_cohesive_host_bond_count(again) == sbc_cohesive_host_bond_count(h));
            CHECK(sbc_cohesive_host_bonds_initial(again) == sbc_cohesive_host_bonds_initial(h));
            free(state);
            sbc_cohesive_host_free(h);
            h = again;
        }
        if (sbc_engine_step(e, &err) != SBC_OK || sbc_cohesive_host_loads(h, xy, v, w, dt, load) != 0) {
            CHECK(0);
            break;
        }
        /* pair by pair, each disc's loads summed in the engine's order (pairs (i, j > i) by j) */
        memset(lp, 0, sizeof lp);
        sums_p[0] = sums_p[1] = sums_p[2] = sums_p[3] = 0.0;
        intact_p = 0;
        for (i = 0; i < NDISC; ++i) {
            double acc[3] = {0.0, 0.0, 0.0}, ld[6];
            for (j = i + 1; j < NDISC; ++j) {
                const int ends[2] = {i, j};
                intact_p += (int)sbc_cohesive_pairs_step(&law, 1, ends, xp, vp, 2, wp, 1, r, dt, state[i][j], ld,
                                                         sums_p);
                if (state[i][j][0] == 0.0 && state[i][j][1] == 0.0 && state[i][j][2] == 0.0 && ld[0] == 0.0 &&
                    ld[1] == 0.0 && ld[2] == 0.0)
                    continue; /* no load: the engine's loop skips the pair */
                acc[0] += ld[0];
                acc[1] += ld[1];
                acc[2] += ld[2];
                lp[3 * j] += ld[3];
                lp[3 * j + 1] += ld[4];
                lp[3 * j + 2] += ld[5];
            }
            lp[3 * i] += acc[0];
            lp[3 * i + 1] += acc[1];
            lp[3 * i + 2] += acc[2];
        }
        advance(xp, vp, wp, lp, rho, dt);
        advance(xy, v, w, load, rho, dt);
    }
    {
        sbc_engine_view view = sbc_engine_get_view(e);
        double moved = 0.0;
        for (k = 0; k < 2 * NDISC; ++k) {
            worst = fmax(worst, fabs(view.x[k] - xy[k]));
            moved = fmax(moved, fabs(view.x[k] - x0[k]));
        }
        /* the check means something only if the packing moved */
        CHECK(moved > 1e-7 * R);
        /* and some bonds broke (measured: 25 of 29 intact after 4000 steps) */
        CHECK(view.bond_count < view.bonds_initial && view.bond_count > 0);
        CHECK(sbc_cohesive_host_bond_count(h) == view.bond_count);
        /* the pair path: the same pairs in the same order, so the same bits */
        CHECK(intact_p == view.bond_count);
        for (k = 0; k < 2 * NDISC; ++k)
            worst = fmax(worst, fabs(view.x[k] - xp[k]));
        sbc_cohesive_host_sums(h, sums_h);
        for (k = 0; k < 4; ++k)
            CHECK_ABS(sums_p[k], sums_h[k], 1e-12 * fabs(sums_h[k]));
    }
    sbc_engine_free(e);
    sbc_cohesive_host_free(h);
    return worst;
}

/* the candidate pairs of the distributed path against every pair by hand */
static void candidates(void)
{
    double x[2 * NDISC], r[NDISC];
    const double reach = 0.3 * R;
    int *pairs = NULL, k, i, j, by_hand = 0, ordered = 1;
    char msg[256];
    long count;
    for (k = 0; k < NDISC; ++k) { /* a lattice whose rows are 2.2 R apart and columns 2 R: some pairs within reach */
        x[2 * k] = 2.0 * R * (k % SIDE) + 0.05 * R * (k % 3);
        x[2 * k + 1] = 2.2 * R * (k / SIDE);
        r[k] = R * (1.0 + 0.01 * (k % 5));
    }
    for (i = 0; i < NDISC; ++i)
        for (j = i + 1; j < NDISC; ++j) {
            const double dx = x[2 * j] - x[2 * i], dy = x[2 * j + 1] - x[2 * i + 1], cut = r[i] + r[j] + reach;
            by_hand += dx * dx + dy * dy < cut * cut;
        }
    count = sbc_cohesive_host_pairs(NDISC, x, r, reach, &pairs, msg, sizeof msg);
    CHECK(count == by_hand && by_hand > 0);
    for (k = 0; k < count && pairs; ++k)
        ordered &= pairs[2 * k] < pairs[2 * k + 1];
    CHECK(ordered);
    sbc_cohesive_host_pairs_free(pairs);
    printf("cohesive-host: %ld candidate pairs within R_a + R_b + 0.3 R of %d discs (by hand %d)\n", count, NDISC,
           by_hand);
    r[3] = -R;
    CHECK(sbc_cohesive_host_pairs(NDISC, x, r, reach, &pairs, msg, sizeof msg) == -1 && strstr(msg, "disc 3"));
}

static void refusals(void)
{
    const double x[4] = {0, 0, 2 * R, 0}, apart[4] = {0, 0, 3 * R, 0}, r[2] = {R, R};
    char msg[256];
    sbc_cohesive_host *h;
    h = sbc_cohesive_host_create("kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2", 2, x, r, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, "missing values") && strstr(msg, "mu MU"));
    h = sbc_cohesive_host_create("kn 1e8 ks 4e7 kr 20 fn zero fs 60 mr 0.2 mu 0.6", 2, x, r, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, "fn 'zero' is not a number"));
    h = sbc_cohesive_host_create("kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr -1 mu 0.6", 2, x, r, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, "mr '-1' is not valid") && strstr(msg, "> 0"));
    h = sbc_cohesive_host_create("kn 1e8 ks 4e7 kr 20 fn 300 fs 60 mr 0.2 mu 0.6 extra", 2, x, r, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, "extra value 'extra'"));
    h = sbc_cohesive_host_create(TABLE6, 2, apart, r, msg, sizeof msg);
    CHECK(h == NULL && strstr(msg, "no two of the 2 discs touch"));
    h = sbc_cohesive_host_create(TABLE6, 2, x, r, msg, sizeof msg);
    CHECK(h != NULL);
    if (h) {
        const double bad[7] = {3, 0, 1, 0, 0, 0, 0}; /* one record: pair (0, 1) of a 2-disc host is fine, */
        CHECK(sbc_cohesive_host_state_set(h, bad, 6) == 1);  /* but 6 values are not 2 + 5 k */
        CHECK(strstr(sbc_cohesive_host_message(h), "not a pair state") != NULL);
        CHECK(sbc_cohesive_host_state_set(h, (const double[7]){1, 1, 1, 0, 1, 0, 0}, 7) == 1); /* i >= j */
        CHECK(strstr(sbc_cohesive_host_message(h), "pair record 0") != NULL);
        sbc_cohesive_host_free(h);
    }
}

void test_cohesive_host(void)
{
    double d;
    one_bond();
    /* the same update in the same order: the two paths agree to round-off */
    d = against_engine(4000, -1);
    CHECK_ABS(d, 0.0, 1e-12 * R);
    printf("cohesive-host: host path and pair path against the embedded engine after 4000 steps: %.3g m\n", d);
    d = against_engine(4000, 1500);
    CHECK_ABS(d, 0.0, 1e-12 * R);
    candidates();
    refusals();
}
