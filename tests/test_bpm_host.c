/* The 3D bond models behind a host's own integrator (bpm_host.h), as YADE
 * uses them: one bond's axial force against E A / L and k^n A, a beam chain
 * integrated here (a leapfrog with local damping, as YADE's NewtonIntegrator)
 * against eq. B1, and the refusals. */
#include "check.h"
#include "tests.h"

#include "sbc/bpm_host.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const double R = 0.1, EB = 4e9, NUB = 0.3;

static void one_bond(void)
{
    const double x[6] = {0, 0, 0, 2 * R, 0, 0}, r[2] = {R, R}, m[2] = {1, 1}, dt = 1e-6, vb = 1e-3;
    double v[6] = {0, 0, 0, vb, 0, 0}, w[6] = {0}, load[12];
    const double A = SBC_PI * R * R;
    int model;
    for (model = 0; model < 2; ++model) {
        char msg[256];
        sbc_bpm *e = sbc_bpm_host_create(model ? "parallel" : "beam", EB, NUB, 1.0, NULL, 2, x, r, m, msg, sizeof msg);
        /* beam: E A / L; parallel bond: k^n A with k^n = E / 2 r_p (Table 3) */
        const double k = model ? EB / (2 * R) * A : EB * A / (2 * R);
        CHECK(e != NULL);
        if (!e)
            continue;
        CHECK(sbc_bpm_host_bond_count(e) == 1);
        CHECK(sbc_bpm_host_loads(e, x, v, w, dt, load) == 0);
        CHECK_REL(load[0], k * vb * dt, 1e-12);  /* A pulled towards B */
        CHECK_REL(load[6], -k * vb * dt, 1e-12); /* B pulled back */
        CHECK_ABS(load[1] + load[2] + load[7] + load[8], 0.0, 1e-12 * k * vb * dt);
        CHECK_REL(sbc_bpm_host_strain_energy(e), 0.5 * k * vb * dt * vb * dt, 1e-9);
        sbc_bpm_free(e);
    }
}

/* a simply supported chain of n spheres (pinned left, roller right), 1 kN
 * at midspan, settled through the host path; returns the midspan deflection
 * (m), 0 on failure */
static double host_chain(int n, const char *model)
{
    double x[33], v[33] = {0}, w[33] = {0}, r[11], m[11], I[11], load[66];
    const double F = 1e3, Le = 2 * R * (n - 1), G = EB / (2 * (1 + NUB)), rho = 925.0, damping = 0.2;
    const double d_b1 = F * Le * Le * Le / (48 * EB * 0.25 * SBC_PI * R * R * R * R) +
                        F * Le * (10.0 / 9.0) / (4 * G * SBC_PI * R * R); /* eq. B1, the scale of "settled" */
    /* blocked degrees of freedom, bits x y z, rot x y z (YADE's 'xyzXZ', 'yzXZ') */
    const unsigned pinned = 1 | 2 | 4 | 8 | 32, roller = 2 | 4 | 8 | 32;
    char msg[256];
    sbc_bpm *e;
    double dt, d = 0.0, prev;
    int i, k, mid = n / 2, chunk = 0;
    for (i = 0; i < n; ++i) {
        x[3 * i] = 2 * R * i;
        x[3 * i + 1] = x[3 * i + 2] = 0.0;
        r[i] = R;
        m[i] = rho * 4.0 / 3.0 * SBC_PI * R * R * R;
        I[i] = 0.4 * m[i] * R * R;
    }
    e = sbc_bpm_host_create(model, EB, NUB, 1.0, NULL, n, x, r, m, msg, sizeof msg);
    CHECK(e != NULL && sbc_bpm_host_bond_count(e) == n - 1);
    if (!e)
        return 0.0;
    dt = 0.5 * sbc_bpm_critical_dt(e);
    do {
        int t;
        prev = d;
        for (t = 0; t < 2000; ++t) {
            if (sbc_bpm_host_loads(e, x, v, w, dt, load) != 0) {
                CHECK(!"finite loads");
                break;
            }
            load[6 * mid + 2] -= F;
            for (i = 0; i < n; ++i) {
                const unsigned blocked = i == 0 ? pinned : i == n - 1 ? roller : 0;
                for (k = 0; k < 6; ++k) {
                    double *vel = k < 3 ? &v[3 * i + k] : &w[3 * i + k - 3], f = load[6 * i + k];
                    if (blocked & (1u << k))
                        continue;
                    if (*vel != 0.0) /* local non-viscous damping, as YADE's */
                        f -= damping * fabs(f) * (*vel > 0.0 ? 1.0 : -1.0);
                    *vel += dt * f / (k < 3 ? m[i] : I[i]);
                }
                for (k = 0; k < 3; ++k)
                    x[3 * i + k] += dt * v[3 * i + k];
            }
        }
        d = -x[3 * mid + 2];
    } while (++chunk < 1000 && fabs(d - prev) > 1e-9 * d_b1);
    CHECK(chunk < 1000);
    sbc_bpm_free(e);
    return d;
}

/* the same chain with parallel bonds on the embedded 3D engine (dashpots,
 * its own integration): the reference for the host path */
static double engine_chain(int n)
{
    sbc_bpm_settings set = sbc_bpm_settings_default();
    sbc_bpm *e = NULL;
    sbc_error err;
    double d = 0.0, prev;
    int i, mid = n / 2, chunk = 0;
    set.model = SBC_BOND_PARALLEL;
    set.parallel = sbc_bpm_parallel_law(EB, R, 4.2);
    set.xi = 0.5;
    if (sbc_bpm_create(&set, &e, &err) != SBC_OK)
        return 0.0;
    for (i = 0; i < n; ++i) {
        double x[3] = {2 * R * i, 0, 0};
        sbc_bpm_add(e, x, R, 925.0, NULL, &err);
    }
    sbc_bpm_bond_touching(e, &err);
    e->fix[0] = 1 | 2 | 4 | 8 | 32;
    e->fix[n - 1] = 2 | 4 | 8 | 32;
    e->fext[6 * mid + 2] = -1e3;
    e->dt = 0.5 * sbc_bpm_critical_dt(e);
    do {
        int t;
        prev = d;
        for (t = 0; t < 2000; ++t)
            sbc_bpm_step(e, &err);
        d = -e->x[3 * mid + 2];
    } while (++chunk < 1000 && fabs(d - prev) > 1e-10 * fabs(d));
    sbc_bpm_free(e);
    return d;
}

/* restart: a bond set created again from the same spheres, given the saved
 * states, continues with the same loads as the original */
static void state_roundtrip(void)
{
    const double x[9] = {0, 0, 0, 2 * R, 0, 0, 4 * R, 0, 0}, r[3] = {R, R, R}, m[3] = {1, 1, 1}, dt = 1e-6;
    const double v[9] = {0, 0, 0, 1e-3, 2e-4, -3e-4, 0, 0, 0}, w[9] = {0, 1e-3, 0, 0, 0, 2e-3, 0, 0, 0};
    double la[18], lb[18], state[64];
    int model;
    for (model = 0; model < 2; ++model) {
        const char *name = model ? "parallel" : "beam";
        sbc_bpm *a = sbc_bpm_host_create(name, EB, NUB, 1.0, NULL, 3, x, r, m, NULL, 0);
        sbc_bpm *b = sbc_bpm_host_create(name, EB, NUB, 1.0, NULL, 3, x, r, m, NULL, 0);
        int k, per, same = 1;
        CHECK(a && b);
        if (!a || !b)
            continue;
        per = sbc_bpm_host_state_doubles(a);
        CHECK(per == (model ? 13 : 28));
        for (k = 0; k < 5; ++k)
            sbc_bpm_host_loads(a, x, v, w, dt, la);
        for (k = 0; k < sbc_bpm_host_bond_count(a); ++k) {
            sbc_bpm_host_state_get(a, k, state);
            sbc_bpm_host_state_set(b, k, state);
        }
        sbc_bpm_host_loads(a, x, v, w, dt, la);
        sbc_bpm_host_loads(b, x, v, w, dt, lb);
        for (k = 0; k < 18; ++k)
            same &= la[k] == lb[k];
        CHECK(same);
        CHECK(la[0] != 0.0);
        CHECK_REL(sbc_bpm_host_strain_energy(b), sbc_bpm_host_strain_energy(a), 1e-15);
        sbc_bpm_free(a);
        sbc_bpm_free(b);
    }
}

/* failure through the host path: a parallel bond (axial stiffness
 * K = k^n pi R^2 = E pi R / 2) pulled 1e-6 m per step breaks at the first
 * step where K d >= F_t,u, holding K d^2 / 2 (eq. 51's dissipated share);
 * the state of a broken bond survives a restart; pushed back, the contact
 * repels with stiffness K */
static void failure(void)
{
    const double r[2] = {R, R}, m[2] = {1, 1}, dt = 1e-4, K = EB * SBC_PI * R / 2, ft = 1e5;
    const double strength[5] = {ft, 0, 0, 0, 0.5};
    double x[6] = {0, 0, 0, 2 * R, 0, 0}, v[6] = {0, 0, 0, 0.01, 0, 0}, w[6] = {0}, load[12], load2[12], state[32];
    char msg[256];
    sbc_bpm *e = sbc_bpm_host_create("parallel", EB, NUB, 1.0, strength, 2, x, r, m, msg, sizeof msg), *again;
    int s, broke_at = -1, per;
    CHECK(e != NULL);
    if (!e)
        return;
    per = sbc_bpm_host_state_doubles(e);
    CHECK(per == 13 + 1 + 7);
    for (s = 1; s <= 200; ++s) {
        x[3] += dt * v[3];
        sbc_bpm_host_loads(e, x, v, w, dt, load);
        if (broke_at < 0 && sbc_bpm_host_intact(e) == 0)
            broke_at = s;
        if (s == 100)
            CHECK_REL(load[6], -K * 1e-4, 1e-9); /* B (6 loads per sphere) pulled back */
    }
    CHECK(broke_at == 160); /* K 1.59e-4 = 99 903 N < 1e5 <= K 1.6e-4 */
    CHECK_ABS(load[6], 0.0, 0);
    CHECK_REL(sbc_bpm_host_dissipated(e), 0.5 * K * 1.6e-4 * 1.6e-4, 1e-9);
    /* a restart: the broken flag, the contact and the fracture energy come back */
    again = sbc_bpm_host_create("parallel", EB, NUB, 1.0, strength, 2, (const double[6]){0, 0, 0, 2 * R, 0, 0}, r, m,
                                msg, sizeof msg);
    CHECK(again != NULL);
    if (again) {
        sbc_bpm_host_state_get(e, 0, state);
        sbc_bpm_host_state_set(again, 0, state);
        sbc_bpm_host_set_fracture_energy(again, sbc_bpm_host_fracture_energy(e));
        CHECK(sbc_bpm_host_intact(again) == 0);
        CHECK_REL(sbc_bpm_host_dissipated(again), sbc_bpm_host_dissipated(e), 1e-15);
    }
    v[3] = -0.01;
    for (s = 1; s <= 250; ++s) { /* back to an overlap of 5e-5 m */
        x[3] += dt * v[3];
        sbc_bpm_host_loads(e, x, v, w, dt, load);
        if (again)
            sbc_bpm_host_loads(again, x, v, w, dt, load2);
    }
    CHECK_REL(load[6], K * 5e-5, 1e-9);
    CHECK(again && load2[6] == load[6]);
    sbc_bpm_free(again);
    sbc_bpm_free(e);
    CHECK(!sbc_bpm_host_create("beam", EB, NUB, 1.0, (const double[5]){0, 1, 1, 1, 0}, 2, x, r, m, msg, sizeof msg) &&
          strstr(msg, "expected a tension > 0 N"));
}

/* Bonds kept with their spheres (the distributed path of LAMMPS and
 * LIGGGHTS) against the whole-array path: a 3 x 3 x 3 lattice with a
 * strength (bonds break on the way), random motions for 400 steps; each
 * sphere sums its bonds in its partners' order (ascending), as a rank does.
 * Loads, broken bonds, fracture and strain energies agree to 1e-12. */
static void kept_with_spheres(void)
{
    enum { N = 27, STEPS = 400 };
    const double strength[5] = {2e4, 3e4, 0, 0, 0.3}, dt = 1e-6;
    double x[3 * N], r[N], m[N], v[3 * N], w[3 * N], load[6 * N], mine[6 * N], worst = 0.0, scale = 0.0;
    int model;
    unsigned seed = 12345u;
    for (model = 0; model < 2; ++model) {
        char msg[256];
        const char *name = model ? "parallel" : "beam";
        sbc_bpm *whole, *law;
        int *pairs = NULL, i, s, per, broke_whole = 0, broke_mine = 0, bad_steps = 0;
        long np, p;
        double *state, fracture = 0.0, strain_whole, strain_mine = 0.0;
        for (i = 0; i < N; ++i) {
            x[3 * i] = 2 * R * (i % 3);
            x[3 * i + 1] = 2 * R * (i / 3 % 3);
            x[3 * i + 2] = 2 * R * (i / 9);
            r[i] = R;
            m[i] = 30.0;
        }
        whole = sbc_bpm_host_create(name, EB, NUB, 1.0, strength, N, x, r, m, msg, sizeof msg);
        law = sbc_bpm_host_law(name, EB, NUB, 1.0, strength, R, msg, sizeof msg);
        CHECK(whole != NULL && law != NULL);
        if (!whole || !law) {
            sbc_bpm_free(whole);
            sbc_bpm_free(law);
            continue;
        }
        np = sbc_bpm_host_pairs(law, N, x, r, &pairs, msg, sizeof msg);
        CHECK(np == sbc_bpm_host_bond_count(whole) && np == 54);
        per = sbc_bpm_host_state_doubles(law);
        CHECK(per == sbc_bpm_host_state_doubles(whole));
        state = calloc((size_t)(np > 0 ? np : 1) * (size_t)per, sizeof *state);
        for (p = 0; p < np; ++p) {
            const int a = pairs[2 * p], b = pairs[2 * p + 1];
            sbc_bpm_host_bond_start(law, &x[3 * a], r[a], &x[3 * b], r[b], &state[p * per]);
        }
        for (s = 0; s < STEPS; ++s) {
            for (i = 0; i < 3 * N; ++i) {
                seed = seed * 1103515245u + 12345u;
                v[i] = 2e-3 * ((double)(seed >> 8) / 16777216.0 - 0.5) + (i % 3 == 0 ? 0.1 * (i / 3 % 3) : 0.0);
                seed = seed * 1103515245u + 12345u;
                w[i] = 1e-2 * ((double)(seed >> 8) / 16777216.0 - 0.5);
            }
            bad_steps += sbc_bpm_host_loads(whole, x, v, w, dt, load) != 0;
            memset(mine, 0, sizeof mine);
            for (i = 0; i < N; ++i) { /* sphere i: its bonds by ascending partner */
                int q;
                for (q = 0; q < N; ++q)
                    for (p = 0; p < np; ++p) {
                        const int a = pairs[2 * p], b = pairs[2 * p + 1];
                        double other[6] = {0}, f = 0.0;
                        if (!((a == i && b == q) || (b == i && a == q)))
                            continue;
                        if (a == i) { /* the copy this sphere keeps advances here; its partner's alike */
                            double copy[64];
                            memcpy(copy, &state[p * per], (size_t)per * sizeof *copy);
                            (void)sbc_bpm_host_bond_step(law, copy, &x[3 * a], r[a], &v[3 * a], &w[3 * a], &x[3 * b],
                                                         r[b], &v[3 * b], &w[3 * b], dt, &mine[6 * i], other, &f);
                        } else {
                            broke_mine += sbc_bpm_host_bond_step(law, &state[p * per], &x[3 * a], r[a], &v[3 * a],
                                                                 &w[3 * a], &x[3 * b], r[b], &v[3 * b], &w[3 * b],
                                                                 dt, other, &mine[6 * i], &f);
                            fracture += f;
                        }
                    }
            }
            for (i = 0; i < 6 * N; ++i) {
                double d = fabs(mine[i] - load[i]);
                if (d > worst) worst = d;
                if (fabs(load[i]) > scale) scale = fabs(load[i]);
            }
            for (i = 0; i < 3 * N; ++i)
                x[i] += dt * v[i];
        }
        broke_whole = sbc_bpm_host_bond_count(whole) - sbc_bpm_host_intact(whole);
        for (p = 0; p < np; ++p) {
            const int a = pairs[2 * p], b = pairs[2 * p + 1];
            double u, fr;
            sbc_bpm_host_bond_energies(law, &state[p * per], &x[3 * a], r[a], &x[3 * b], r[b], &u, &fr);
            strain_mine += u;
        }
        strain_whole = sbc_bpm_host_strain_energy(whole);
        printf("  bonds kept with their spheres (%s): %d of %ld broke (whole arrays %d), loads within %.2g of %.3g N, "
               "strain %.6g J (whole %.6g), fracture %.6g J (whole %.6g)\n",
               name, broke_mine, np, broke_whole, worst, scale, strain_mine, strain_whole, fracture,
               sbc_bpm_host_fracture_energy(whole));
        CHECK(bad_steps == 0);
        CHECK(broke_mine == broke_whole && broke_mine > 0 && broke_mine < np);
        CHECK(worst <= 1e-12 * scale && scale > 0.0);
        CHECK_REL(strain_mine, strain_whole, 1e-12);
        CHECK_REL(fracture, sbc_bpm_host_fracture_energy(whole), 1e-12);
        free(state);
        sbc_bpm_host_pairs_free(pairs);
        sbc_bpm_free(whole);
        sbc_bpm_free(law);
        worst = scale = 0.0;
        fracture = 0.0;
    }
}

static void refusals(void)
{
    const double x[6] = {0, 0, 0, 1, 0, 0}, r[2] = {R, R}, m[2] = {1, 1};
    char msg[256] = "";
    CHECK(!sbc_bpm_host_create("rope", EB, NUB, 1.0, NULL, 2, x, r, m, msg, sizeof msg) &&
          strstr(msg, "model must be beam or parallel"));
    CHECK(!sbc_bpm_host_create("beam", EB, NUB, 1.0, NULL, 2, x, r, m, msg, sizeof msg) &&
          strstr(msg, "no two spheres touch"));
    CHECK(!sbc_bpm_host_create("beam", -1.0, NUB, 1.0, NULL, 2, x, r, m, msg, sizeof msg) && strstr(msg, "E -1 Pa"));
    CHECK(!sbc_bpm_host_create("beam", EB, NUB, 1.0, NULL, 1, x, r, m, msg, sizeof msg) && strstr(msg, "fewer than 2"));
}

void test_bpm_host(void)
{
    static const int sizes[] = {3, 5, 7, 11};
    size_t k;
    one_bond();
    failure();
    kept_with_spheres();
    for (k = 0; k < sizeof sizes / sizeof sizes[0]; ++k) {
        const int n = sizes[k];
        const double Le = 2 * R * (n - 1), G = EB / (2 * (1 + NUB));
        const double d_b1 = 1e3 * Le * Le * Le / (48 * EB * 0.25 * SBC_PI * R * R * R * R) +
                            1e3 * Le * (10.0 / 9.0) / (4 * G * SBC_PI * R * R);
        const double dp = host_chain(n, "parallel"), de = engine_chain(n);
        if (getenv("SBC_TEST_VERBOSE"))
            printf("  parallel chain of %d: host %.17g, engine %.17g, relative %.2g\n", n, dp, de, (dp - de) / de);
        CHECK_REL(host_chain(n, "beam"), d_b1, 1e-4); /* eq. B1 */
        /* parallel bonds: the host path (local damping) against the embedded
         * engine (dashpots). Measured: 1.4e-8, 4.9e-8, 1.4e-7, 1.0e-6 for 3, 5, 7,
         * 11 spheres, growing with the chain's deflection, while the beam's
         * fixed-stiffness law settles to eq. B1 to 1e-12 on both paths. The
         * parallel bond accumulates its forces increment by increment along the
         * bond normal of each step (eqs. 10-17), so the state it settles in
         * depends on the path it took there at that order (our reading); 1e-5
         * bounds it with room. */
        CHECK(dp > 0.0);
        CHECK_REL(dp, de, 1e-5);
    }
    state_roundtrip();
    refusals();
}
