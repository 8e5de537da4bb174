#include "sbc/packing.h"

#include "sbc/settings.h"
#include "words.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sbc_packing_free(sbc_packing *p)
{
    free(p->x);
    free(p->r);
    memset(p, 0, sizeof *p);
}

static sbc_status reserve(sbc_packing *p, int n, sbc_error *err)
{
    double *x = realloc(p->x, sizeof(double) * 2 * (size_t)n), *r;
    if (!x)
        return sbc_fail(err, SBC_ERR_NOMEM, "packing: out of memory for %d particles", n);
    p->x = x;
    r = realloc(p->r, sizeof(double) * (size_t)n);
    if (!r)
        return sbc_fail(err, SBC_ERR_NOMEM, "packing: out of memory for %d particles", n);
    p->r = r;
    return SBC_OK;
}

sbc_status sbc_packing_lattice_square(sbc_packing *p, int nx, int ny, double spacing, double radius,
                                      sbc_error *err)
{
    int a, b, k = 0;
    memset(p, 0, sizeof *p);
    if (nx < 1 || ny < 1 || (long)nx * ny > 100000000L)
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: %d x %d particles (expected 1 to 1e8 in all)", nx, ny);
    if (!(spacing > 0.0) || !(radius > 0.0))
        return sbc_fail(err, SBC_ERR_INPUT, "lattice: spacing %g and radius %g must be positive", spacing, radius);
    if (reserve(p, nx * ny, err) != SBC_OK)
        return SBC_ERR_NOMEM;
    for (b = 0; b < ny; ++b) {
        for (a = 0; a < nx; ++a, ++k) {
            p->x[2 * k] = a * spacing;
            p->x[2 * k + 1] = b * spacing;
            p->r[k] = radius;
        }
    }
    p->n = k;
    return SBC_OK;
}

sbc_status sbc_packing_read(sbc_packing *p, const char *path, sbc_error *err)
{
    FILE *fp = fopen(path, "r");
    char line[1024];
    int lineno = 0, cap = 0;
    sbc_status st = SBC_OK;
    memset(p, 0, sizeof *p);
    if (!fp)
        return sbc_fail(err, SBC_ERR_IO, "read_packing: cannot open '%s'", path);
    while (fgets(line, sizeof line, fp)) {
        char *tok[3];
        const char *names[3] = {"x", "y", "r"};
        double v[3];
        int nt = sbc_split_words(line, tok, 3), c;
        ++lineno;
        if (nt == 0)
            continue;
        if (nt != 3) {
            st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: %d values (expected 3: x y r)", path, lineno,
                          nt);
            break;
        }
        for (c = 0; c < 3 && st == SBC_OK; ++c)
            if (sbc_parse_real(tok[c], names[c], &v[c], NULL) != SBC_OK)
                st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: %s value '%s' is not a number", path,
                              lineno, names[c], tok[c]);
        if (st != SBC_OK)
            break;
        if (!(v[2] > 0.0)) {
            st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: radius %g is not positive", path, lineno,
                          v[2]);
            break;
        }
        if (p->n == cap) {
            cap = cap ? 2 * cap : 256;
            if ((st = reserve(p, cap, err)) != SBC_OK)
                break;
        }
        p->x[2 * p->n] = v[0];
        p->x[2 * p->n + 1] = v[1];
        p->r[p->n++] = v[2];
    }
    fclose(fp);
    if (st == SBC_OK && p->n == 0)
        st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s holds no particles", path);
    if (st != SBC_OK)
        sbc_packing_free(p);
    return st;
}
