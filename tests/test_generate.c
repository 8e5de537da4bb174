/* Packing generator (Sect. 4.2): deterministic per seed, no overlaps beyond the
 * relaxation tolerance, periodic copies at exactly +-L, one corner particle on
 * all four corners. */
#include "check.h"
#include "tests.h"

#include "sbc/generate.h"

#include <string.h>

void test_generate(void)
{
    sbc_generate_def d = sbc_generate_def_default();
    sbc_packing a, b;
    sbc_generate_info ia, ib;
    sbc_error err;
    int i, j, overlaps = 0, unpaired = 0, corners = 0;
    double L, tol;
    d.n = 25;
    CHECK(sbc_generate_periodic(&d, &a, &ia, &err) == SBC_OK);
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    CHECK(a.n == b.n && memcmp(a.x, b.x, sizeof(double) * 2 * (size_t)a.n) == 0 &&
          memcmp(a.r, b.r, sizeof(double) * (size_t)a.n) == 0);
    d.seed = 2;
    sbc_packing_free(&b);
    CHECK(sbc_generate_periodic(&d, &b, &ib, &err) == SBC_OK);
    CHECK(b.n != a.n || memcmp(a.x, b.x, sizeof(double) * 2 * (size_t)a.n) != 0);
    L = ia.L;
    tol = 1e-9 * d.r_min;
    CHECK(ia.n > ia.n0 && ia.fraction > 0.80 && ia.fraction < 0.87);
    for (i = 0; i < a.n; ++i) {
        double x = a.x[2 * i], y = a.x[2 * i + 1], r = a.r[i];
        CHECK(r >= d.r_min && r <= 2.0 * d.r_min);
        for (j = i + 1; j < a.n; ++j) {
            double dx = a.x[2 * j] - x, dy = a.x[2 * j + 1] - y;
            if (sqrt(dx * dx + dy * dy) < a.r[j] + r - tol) ++overlaps;
        }
        /* a disc crossing an edge has its copy at exactly +-L on the other side */
        if (x - r < 0.0 || x + r > L) {
            double want = x - r < 0.0 ? x + L : x - L;
            int found = 0;
            for (j = 0; j < a.n; ++j)
                found |= a.x[2 * j] == want && a.x[2 * j + 1] == y && a.r[j] == r;
            unpaired += !found;
        }
        if (y - r < 0.0 || y + r > L) {
            double want = y - r < 0.0 ? y + L : y - L;
            int found = 0;
            for (j = 0; j < a.n; ++j)
                found |= a.x[2 * j + 1] == want && a.x[2 * j] == x && a.r[j] == r;
            unpaired += !found;
        }
        corners += (x == 0.0 || x == L) && (y == 0.0 || y == L);
    }
    CHECK(overlaps == 0);
    CHECK(unpaired == 0);
    CHECK(corners == 4);
    sbc_packing_free(&a);
    sbc_packing_free(&b);
}
