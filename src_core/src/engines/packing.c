#include "sbc/packing.h"

#include "sbc/settings.h"
#include "base/words.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void sbc_packing_free(sbc_packing *p)
{
    free(p->x);
    free(p->r);
    memset(p, 0, sizeof *p);
}

/* room for n particles of dim coordinates in *x, *r */
static sbc_status reserve_arrays(int dim, double **x, double **r, int n, sbc_error *err)
{
    double *nx = realloc(*x, sizeof(double) * (size_t)dim * (size_t)n), *nr;
    if (!nx)
        return sbc_fail(err, SBC_ERR_NOMEM, "packing: out of memory for %d particles", n);
    *x = nx;
    nr = realloc(*r, sizeof(double) * (size_t)n);
    if (!nr)
        return sbc_fail(err, SBC_ERR_NOMEM, "packing: out of memory for %d particles", n);
    *r = nr;
    return SBC_OK;
}

static sbc_status reserve(sbc_packing *p, int n, sbc_error *err) { return reserve_arrays(2, &p->x, &p->r, n, err); }

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

/* "box XLO XHI YLO YHI" */
static sbc_status read_box(sbc_packing *p, char *line, const char *path, int lineno, sbc_error *err)
{
    static const char *names[4] = {"XLO", "XHI", "YLO", "YHI"};
    char *tok[6];
    int nt = sbc_split_words(line, tok, 6), c;
    if (p->has_box)
        return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: a second 'box' line", path, lineno);
    if (nt != 5)
        return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: box has %d values (expected 4: XLO XHI YLO YHI)",
                        path, lineno, nt - 1);
    for (c = 0; c < 4; ++c)
        if (sbc_parse_real(tok[c + 1], names[c], &p->box[c], NULL) != SBC_OK)
            return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: box %s value '%s' is not a number", path,
                            lineno, names[c], tok[c + 1]);
    if (!(p->box[1] > p->box[0] && p->box[3] > p->box[2]))
        return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: box %g %g %g %g is empty (expected XLO < XHI, "
                        "YLO < YHI)", path, lineno, p->box[0], p->box[1], p->box[2], p->box[3]);
    p->has_box = 1;
    return SBC_OK;
}

/* One line of a packing file into line (cap bytes, without the newline);
 * *end = 1 at the end of the file. A line is read whole or refused:
 * longer than cap - 1 characters, or holding a NUL byte (a binary file,
 * /dev/zero), is an error, never a split into two particles or a read
 * without end. */
static sbc_status read_line(FILE *fp, char *line, size_t cap, const char *path, int lineno, int *end,
                            const char *expected, sbc_error *err)
{
    size_t n = 0;
    int ch;
    *end = 0;
    while ((ch = getc(fp)) != EOF && ch != '\n') {
        if (ch == '\0')
            return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d holds a NUL byte (expected text: %s)",
                            path, lineno, expected);
        if (n + 1 >= cap)
            return sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d is longer than %d characters (expected %s)",
                            path, lineno, (int)cap - 1, expected);
        line[n++] = (char)ch;
    }
    *end = ch == EOF && n == 0;
    line[n] = '\0';
    return SBC_OK;
}

sbc_status sbc_packing_read(sbc_packing *p, const char *path, sbc_error *err)
{
    FILE *fp = fopen(path, "r");
    sbc_status st;
    memset(p, 0, sizeof *p);
    if (!fp)
        return sbc_fail(err, SBC_ERR_IO, "read_packing: cannot open '%s'", path);
    st = sbc_packing_read_stream(p, fp, path, err);
    fclose(fp);
    return st;
}

typedef struct by_x {
    double x;
    int k;
} by_x;

static int compare_x(const void *a, const void *b)
{
    double xa = ((const by_x *)a)->x, xb = ((const by_x *)b)->x;
    return (xa > xb) - (xa < xb);
}

/* the first pair a < b of the n particles (centres x [dim n], radii r [n]) whose centres are closer than 1e-6 of
   the smaller radius in every coordinate: 1 and the pair, 0 when none (-1 out of memory) */
static int coincident(int dim, int n, const double *x, const double *r, int *pa, int *pb)
{
    by_x *order;
    double rmin = HUGE_VAL;
    int i, j, c, found = 0;
    if (n < 2)
        return 0;
    if (!(order = malloc(sizeof *order * (size_t)n)))
        return -1;
    for (i = 0; i < n; ++i) {
        order[i].x = x[dim * i];
        order[i].k = i;
        rmin = fmin(rmin, r[i]);
    }
    qsort(order, (size_t)n, sizeof *order, compare_x);
    for (i = 0; i < n && !found; ++i)
        for (j = i + 1; j < n && !found && order[j].x - order[i].x < 1e-6 * rmin; ++j) {
            const int a = order[i].k < order[j].k ? order[i].k : order[j].k;
            const int b = order[i].k < order[j].k ? order[j].k : order[i].k;
            const double near = 1e-6 * fmin(r[a], r[b]);
            for (c = 0; c < dim && fabs(x[dim * b + c] - x[dim * a + c]) < near; ++c)
                ;
            if (c == dim) {
                *pa = a;
                *pb = b;
                found = 1;
            }
        }
    free(order);
    return found;
}

/* The rows of a packing file: dim coordinates and a radius per line (m) into
 * *x [dim n], *r [n], *n; a 'box' line into box (2D; NULL: no box line) */
static sbc_status read_rows(FILE *fp, const char *path, int dim, sbc_packing *box, double **x, double **r, int *n,
                            sbc_error *err)
{
    static const char *const names[2][4] = {{"x", "y", "r", ""}, {"x", "y", "z", "r"}};
    const char *const expected = dim == 2 ? "x y r" : "x y z r";
    const int nv = dim + 1;
    char line[1024];
    int lineno = 0, cap = 0, end = 0, *line_of = NULL, a = 0, b = 0, found;
    long announced = -1; /* the count servo_bc's first line gives ("# servo_bc packing: 121 discs, ...") */
    sbc_status st = SBC_OK;
    while ((st = read_line(fp, line, sizeof line, path, lineno + 1, &end, expected, err)) == SBC_OK && !end) {
        char *tok[4], line_copy[1024];
        const char *const *name = names[dim - 2];
        double v[4];
        int nt, c;
        ++lineno;
        if (lineno == 1 && sscanf(line, "# servo_bc packing: %ld", &announced) != 1)
            announced = -1;
        memcpy(line_copy, line, sizeof line);
        nt = sbc_split_words(line, tok, nv);
        if (nt == 0)
            continue;
        if (box && strcmp(tok[0], "box") == 0) {
            st = read_box(box, line_copy, path, lineno, err);
            if (st != SBC_OK)
                break;
            continue;
        }
        if (nt != nv) {
            st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: %d values (expected %d: %s)", path, lineno,
                          nt, nv, expected);
            break;
        }
        for (c = 0; c < nv && st == SBC_OK; ++c)
            if (sbc_parse_real(tok[c], name[c], &v[c], NULL) != SBC_OK)
                st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: %s value '%s' is not a number", path,
                              lineno, name[c], tok[c]);
        if (st != SBC_OK)
            break;
        if (!(v[dim] > 0.0)) {
            st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: radius %g is not positive", path, lineno,
                          v[dim]);
            break;
        }
        if (*n >= SBC_PACKING_MAX) {
            st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s line %d: more than %ld particles", path, lineno,
                          (long)SBC_PACKING_MAX);
            break;
        }
        if (*n == cap) {
            int *grown;
            cap = cap ? 2 * cap : 256;
            if ((st = reserve_arrays(dim, x, r, cap, err)) != SBC_OK)
                break;
            if (!(grown = realloc(line_of, sizeof *line_of * (size_t)cap))) {
                st = sbc_fail(err, SBC_ERR_NOMEM, "read_packing: out of memory");
                break;
            }
            line_of = grown;
        }
        for (c = 0; c < dim; ++c)
            (*x)[dim * *n + c] = v[c];
        line_of[*n] = lineno;
        (*r)[(*n)++] = v[dim];
    }
    if (st == SBC_OK && *n == 0)
        st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s holds no particles", path);
    if (st == SBC_OK && announced >= 0 && announced != *n)
        st = sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s: its first line announces %ld particles and it holds %d (a "
                      "torn or edited file: write it again, or correct the first line)", path, announced, *n);
    if (st == SBC_OK && (found = coincident(dim, *n, *x, *r, &a, &b)) != 0)
        st = found < 0 ? sbc_fail(err, SBC_ERR_NOMEM, "read_packing: out of memory")
                       : sbc_fail(err, SBC_ERR_INPUT, "read_packing: %s lines %d and %d: %s %d and %d have coincident "
                                  "centres (expected distinct particles: their contact would have no normal)", path,
                                  line_of[a], line_of[b], dim == 3 ? "spheres" : "discs", a, b);
    free(line_of);
    return st;
}

sbc_status sbc_packing_read_stream(sbc_packing *p, FILE *fp, const char *path, sbc_error *err)
{
    sbc_status st;
    memset(p, 0, sizeof *p);
    if ((st = read_rows(fp, path, 2, p, &p->x, &p->r, &p->n, err)) != SBC_OK)
        sbc_packing_free(p);
    return st;
}

sbc_status sbc_spheres_read(const char *path, int *n, double **x, double **r, sbc_error *err)
{
    FILE *fp = fopen(path, "r");
    sbc_status st;
    *n = 0;
    *x = *r = NULL;
    if (!fp)
        return sbc_fail(err, SBC_ERR_IO, "read_packing: cannot open '%s'", path);
    st = read_rows(fp, path, 3, NULL, x, r, n, err);
    fclose(fp);
    if (st != SBC_OK) {
        free(*x);
        free(*r);
        *x = *r = NULL;
        *n = 0;
    }
    return st;
}

/* Sweep along x: pairs closer in x than r_i + r_max + tol only. */
sbc_status sbc_packing_contact_angles(const sbc_packing *p, double tol, double **angle, int *count, sbc_error *err)
{
    by_x *order = malloc(sizeof *order * (size_t)(p->n > 0 ? p->n : 1));
    double rmax = 0.0, *out = NULL;
    int i, j, m = 0, cap = 0;
    *angle = NULL;
    *count = 0;
    if (!order)
        return sbc_fail(err, SBC_ERR_NOMEM, "contacts: out of memory");
    for (i = 0; i < p->n; ++i) {
        order[i].x = p->x[2 * i];
        order[i].k = i;
        if (p->r[i] > rmax) rmax = p->r[i];
    }
    qsort(order, (size_t)p->n, sizeof *order, compare_x);
    for (i = 0; i < p->n; ++i) {
        int a = order[i].k;
        for (j = i + 1; j < p->n && order[j].x - order[i].x < p->r[a] + rmax + tol; ++j) {
            int b = order[j].k;
            double dx = p->x[2 * b] - p->x[2 * a], dy = p->x[2 * b + 1] - p->x[2 * a + 1];
            if (sqrt(dx * dx + dy * dy) >= p->r[a] + p->r[b] + tol)
                continue;
            if (m == cap) {
                double *grown = realloc(out, sizeof *out * (size_t)(cap = cap ? 2 * cap : 256));
                if (!grown) {
                    free(out);
                    free(order);
                    return sbc_fail(err, SBC_ERR_NOMEM, "contacts: out of memory");
                }
                out = grown;
            }
            out[m++] = atan2(dy, dx);
        }
    }
    free(order);
    *angle = out;
    *count = m;
    return SBC_OK;
}

sbc_status sbc_packing_distinct(int n, const double *x, const double *r, sbc_error *err)
{
    int a = 0, b = 0;
    const int found = coincident(2, n, x, r, &a, &b);
    if (found < 0)
        return sbc_fail(err, SBC_ERR_NOMEM, "out of memory");
    if (found)
        return sbc_fail(err, SBC_ERR_INPUT, "particles %d and %d have coincident centres (%g, %g) m (expected distinct "
                        "particles; check the packing)", a, b, x[2 * a], x[2 * a + 1]);
    return SBC_OK;
}
