#define _POSIX_C_SOURCE 200809L
/* replicas K [perturb EPS] [jobs J] (docs/runner.md, "Replicas"): the runs
 * that follow are K histories of the same case, run J at a time as child
 * processes. Replica 0 is the plain run (its results file is the one the
 * servo_bc line names); replica k >= 1 starts from the packing with every
 * interior centre moved by a random vector of length up to EPS R_i (uniform
 * over the disc, in 3D the ball, of that radius; seed k, splitmix64), and writes
 * FILE_replicaKK.csv. The summary FILE_replicas.csv holds, per increment,
 * F of the first replica that reached it, how many did, and the mean,
 * standard deviation, min and max of each sigma component over those
 * replicas: the spread of a path that the presets' stated accuracy (the
 * balance of the state reached) does not bound (docs/speed-accuracy.md). */
#include "script_state.h"

#include "sbc/columns.h"
#include "sbc/frame.h"
#include "sbc/embedded/output_file.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

enum { REPLICAS_MAX = 1000, JOBS_MAX = 64, FIELDS = SBC_COLUMNS };

sbc_status sbc_script_replicas_command(script *s, int nw, char **w, sbc_error *err)
{
    static const char usage[] = "replicas K [perturb EPS] [jobs J]";
    long k = 0, jobs = 2;
    double eps = 1e-6;
    int at;
    if (nw < 2)
        return sbc_fail(err, SBC_ERR_INPUT, "replicas: missing values (expected '%s')", usage);
    if (sbc_parse_int(w[1], "K", 1, REPLICAS_MAX, &k, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "replicas: K '%s' is not valid (expected an integer from 1 to %d)", w[1],
                        REPLICAS_MAX);
    for (at = 2; at < nw; at += 2) {
        if (at + 1 >= nw)
            return sbc_fail(err, SBC_ERR_INPUT, "replicas: keyword '%s' needs a value (expected '%s')", w[at], usage);
        if (strcmp(w[at], "perturb") == 0) {
            if (sbc_parse_real(w[at + 1], "EPS", &eps, NULL) != SBC_OK || !(eps > 0.0 && eps <= 0.1))
                return sbc_fail(err, SBC_ERR_INPUT, "replicas: perturb '%s' is not valid (expected a fraction of the "
                                "radius in (0, 0.1])", w[at + 1]);
        } else if (strcmp(w[at], "jobs") == 0) {
            if (sbc_parse_int(w[at + 1], "J", 1, JOBS_MAX, &jobs, NULL) != SBC_OK)
                return sbc_fail(err, SBC_ERR_INPUT, "replicas: jobs '%s' is not valid (expected an integer from 1 to "
                                "%d)", w[at + 1], JOBS_MAX);
        } else
            return sbc_fail(err, SBC_ERR_INPUT, "replicas: unknown keyword '%s' (expected perturb or jobs)", w[at]);
    }
    s->replicas = (int)k;
    s->perturb = eps;
    s->jobs = (int)jobs;
    return SBC_OK;
}

/* FILE with "_replicaKK" (k >= 1) or "_replicas" (k < 0) before its extension */
static void replica_name(const char *file, int k, char *out, size_t size)
{
    const char *dot = strrchr(file, '.'), *slash = strrchr(file, '/');
    size_t stem = dot && (!slash || dot > slash) ? (size_t)(dot - file) : strlen(file);
    char tag[32];
    if (k == 0) {
        snprintf(out, size, "%s", file);
        return;
    }
    if (k < 0)
        snprintf(tag, sizeof tag, "_replicas");
    else
        snprintf(tag, sizeof tag, "_replica%02d", k);
    snprintf(out, size, "%.*s%s%s", (int)stem, file, tag, file + stem);
}

static double uniform(uint64_t *state) /* splitmix64, in [0, 1) */
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* replica k's packing: each interior centre moved by up to eps R */
static sbc_status perturb(script *s, int k, sbc_error *err)
{
    const int dim = s->x3 ? 3 : 2, n = dim == 3 ? s->n3 : s->packing.n;
    double *x = dim == 3 ? s->x3 : s->packing.x;
    const double *r = dim == 3 ? s->r3 : s->packing.r;
    sbc_frame frame;
    unsigned char *is_frame = calloc((size_t)(n > 0 ? n : 1), 1);
    uint64_t state = (uint64_t)k;
    sbc_status st;
    int q, i;
    if (!is_frame)
        return sbc_fail(err, SBC_ERR_NOMEM, "replicas: out of memory");
    st = dim == 3 ? sbc_frame_detect_3d(&frame, n, x, r, 0.0, err) : sbc_frame_detect_packing(&frame, &s->packing, err);
    if (st != SBC_OK) {
        free(is_frame);
        return st;
    }
    for (q = 0; q < frame.n; ++q)
        is_frame[frame.particle[q]] = 1;
    sbc_frame_free(&frame);
    for (i = 0; i < n; ++i) {
        const double angle = 2.0 * 3.14159265358979323846 * uniform(&state);
        if (dim == 3) { /* uniform over the ball: a direction on the sphere, the radius as u^(1/3) */
            const double z = 2.0 * uniform(&state) - 1.0, ring = sqrt(fmax(0.0, 1.0 - z * z));
            const double radius = s->perturb * r[i] * cbrt(uniform(&state));
            if (is_frame[i])
                continue;
            x[3 * i] += radius * ring * cos(angle);
            x[3 * i + 1] += radius * ring * sin(angle);
            x[3 * i + 2] += radius * z;
        } else {
            const double radius = s->perturb * r[i] * sqrt(uniform(&state));
            if (is_frame[i])
                continue;
            x[2 * i] += radius * cos(angle);
            x[2 * i + 1] += radius * sin(angle);
        }
    }
    free(is_frame);
    return SBC_OK;
}

/* the child's run: replica k's outputs, its packing, one run; the exit status */
static int run_replica(script *s, sbc_script_run_fn run_once, int k)
{
    sbc_error e;
    sbc_status st = SBC_OK;
    if (k > 0) {
        char file[2 * SBC_NAME_LEN];
        replica_name(s->settings.file, k, file, sizeof file);
        if (strlen(file) >= sizeof s->settings.file) {
            fprintf(stderr, "ERROR: replica %d: the file name '%s' is too long\n", k, file);
            return 1;
        }
        strcpy(s->settings.file, file);
        s->vtk_every = s->network_every = 0; /* pictures and VTK: replica 0's */
        s->plot[0] = '\0';
        s->log = NULL;
        st = perturb(s, k, &e);
    }
    if (st == SBC_OK)
        st = run_once(s, &e);
    if (st != SBC_OK)
        fprintf(stderr, "ERROR: replica %d: %s\n", k, e.message);
    fflush(NULL);
    return st == SBC_OK ? 0 : 1;
}

/* the rows of one results file, their first nf fields: rows[n][FIELDS]; the row count, -1 if unreadable */
static int read_rows(const char *path, int nf, double (**rows)[FIELDS])
{
    FILE *fp = fopen(path, "r");
    char line[4096];
    int n = 0, cap = 0;
    *rows = NULL;
    if (!fp)
        return -1;
    if (!fgets(line, sizeof line, fp)) {
        fclose(fp);
        return 0;
    }
    while (fgets(line, sizeof line, fp)) {
        char *p = line, *end;
        int c;
        if (n == cap) {
            double(*grown)[FIELDS] = realloc(*rows, sizeof **rows * (size_t)(cap = cap ? 2 * cap : 64));
            if (!grown)
                break;
            *rows = grown;
        }
        for (c = 0; c < nf; ++c, p = end + 1) {
            (*rows)[n][c] = strtod(p, &end);
            if (end == p || (c + 1 < nf && *end != ','))
                break;
        }
        if (c < nf)
            break;
        ++n;
    }
    fclose(fp);
    return n;
}

/* the summary of the replicas' files; its path in summary */
static sbc_status summarize(script *s, int K, char *summary, size_t size, int *rows_out, double *spread,
                            double *scale, sbc_error *err)
{
    static const char *const comps[2][9] = {{"11", "12", "21", "22"}, {"11", "12", "13", "21", "22", "23", "31", "32",
                                                                     "33"}};
    const int dim = s->x3 ? 3 : 2, nc = dim * dim;
    double(*rows[REPLICAS_MAX])[FIELDS];
    int n[REPLICAS_MAX], fcol[9], scol[9], rows_all = 0, nf = 0, k, i, c;
    char path[2 * SBC_NAME_LEN];
    FILE *fp;
    sbc_status st = SBC_OK;
    for (c = 0; c < nc; ++c) { /* the columns of F and sigma in a results file of this dimension */
        char name[16];
        snprintf(name, sizeof name, "F%s", comps[dim - 2][c]);
        fcol[c] = sbc_column_index(dim, name);
        snprintf(name, sizeof name, "sigma%s", comps[dim - 2][c]);
        scol[c] = sbc_column_index(dim, name);
        nf = fcol[c] + 1 > nf ? fcol[c] + 1 : nf;
        nf = scol[c] + 1 > nf ? scol[c] + 1 : nf;
    }
    for (k = 0; k < K; ++k) {
        replica_name(s->settings.file, k, path, sizeof path);
        n[k] = read_rows(path, nf, &rows[k]);
        if (n[k] < 0)
            n[k] = 0;
        rows_all = n[k] > rows_all ? n[k] : rows_all; /* the longest; each row over the replicas that reached it */
    }
    replica_name(s->settings.file, -1, summary, size);
    *rows_out = rows_all;
    *spread = *scale = 0.0;
    if (!(fp = sbc_output_open(summary, SBC_OUTPUT_RESULTS, "replicas", err))) {
        st = err->status;
        goto done;
    }
    fprintf(fp, "increment");
    for (c = 0; c < nc; ++c)
        fprintf(fp, ",F%s", comps[dim - 2][c]);
    fprintf(fp, ",replicas");
    for (c = 0; c < nc; ++c) {
        const char *ij = comps[dim - 2][c];
        fprintf(fp, ",sigma%s_mean,sigma%s_std,sigma%s_min,sigma%s_max", ij, ij, ij, ij);
    }
    fprintf(fp, "\n");
    for (i = 0; i < rows_all; ++i) {
        int first = -1, count = 0;
        for (k = 0; k < K; ++k)
            if (n[k] > i) {
                count++;
                if (first < 0) first = k;
            }
        fprintf(fp, "%d", (int)rows[first][i][0]);
        for (c = 0; c < nc; ++c)
            fprintf(fp, ",%.17g", rows[first][i][fcol[c]]);
        fprintf(fp, ",%d", count);
        for (c = 0; c < nc; ++c) {
            double sum = 0.0, sq = 0.0, lo = HUGE_VAL, hi = -HUGE_VAL, mean;
            for (k = 0; k < K; ++k)
                if (n[k] > i) {
                    const double v = rows[k][i][scol[c]];
                    sum += v;
                    lo = fmin(lo, v);
                    hi = fmax(hi, v);
                }
            mean = sum / count;
            for (k = 0; k < K; ++k)
                if (n[k] > i)
                    sq += (rows[k][i][scol[c]] - mean) * (rows[k][i][scol[c]] - mean);
            fprintf(fp, ",%.17g,%.6g,%.17g,%.17g", mean, count > 1 ? sqrt(sq / (count - 1)) : 0.0, lo, hi);
            if (count > 1)
                *spread = fmax(*spread, hi - lo);
            *scale = fmax(*scale, fabs(mean));
        }
        fprintf(fp, "\n");
    }
    if (fclose(fp) != 0)
        st = sbc_fail(err, SBC_ERR_IO, "replicas: cannot write '%s'", summary);
done:
    for (k = 0; k < K; ++k)
        free(rows[k]);
    return st;
}

sbc_status sbc_script_replicas(script *s, sbc_script_run_fn run_once, sbc_error *err)
{
    const int K = s->replicas;
    int status[REPLICAS_MAX], running = 0, next = 0, failed = 0, first_failed = -1, rows, k;
    pid_t pid[REPLICAS_MAX];
    char path[2 * SBC_NAME_LEN], summary[2 * SBC_NAME_LEN];
    double spread, scale;
    sbc_status st;
    if (!s->settings.file[0])
        return sbc_fail(err, SBC_ERR_INPUT, "replicas: the run needs a results file (servo_bc keyword 'file'): the "
                        "summary is made from the replicas' files");
    for (k = 1; k <= K; ++k) { /* the replicas' files and the summary, up front */
        replica_name(s->settings.file, k == K ? -1 : k, path, sizeof path);
        if ((st = sbc_script_files_check(s, path, "replicas:", err)) != SBC_OK ||
            (st = (s->check ? sbc_output_probe : sbc_output_owned)(path, SBC_OUTPUT_RESULTS, "replicas", err)) != SBC_OK)
            return st;
    }
    if (s->check)
        return run_once(s, err);
    if (s->log)
        fprintf(s->log, "replicas: %d histories, %d at a time; replicas 1 to %d move each interior centre by up to "
                "%g R\n", K, s->jobs, K - 1, s->perturb);
    fflush(NULL);
    while (next < K || running > 0) {
        if (next < K && running < s->jobs) {
            pid[next] = fork();
            if (pid[next] < 0)
                return sbc_fail(err, SBC_ERR_IO, "replicas: cannot start replica %d", next);
            if (pid[next] == 0)
                _exit(run_replica(s, run_once, next));
            ++next;
            ++running;
            continue;
        }
        {
            int ws;
            const pid_t done = wait(&ws);
            if (done < 0)
                break;
            for (k = 0; k < next; ++k)
                if (pid[k] == done) {
                    status[k] = WIFEXITED(ws) ? WEXITSTATUS(ws) : 128 + (WIFSIGNALED(ws) ? WTERMSIG(ws) : 0);
                    if (status[k] != 0 && first_failed < 0)
                        first_failed = k;
                    failed += status[k] != 0;
                }
            --running;
        }
    }
    for (k = 1; k < K; ++k) {
        replica_name(s->settings.file, k, path, sizeof path);
        sbc_script_files_note(s, path, "replica's file");
    }
    sbc_script_files_note(s, s->settings.file, "results file");
    if ((st = summarize(s, K, summary, sizeof summary, &rows, &spread, &scale, err)) != SBC_OK)
        return st;
    sbc_script_files_note(s, summary, "replicas' summary");
    if (s->log)
        fprintf(s->log, "replicas: %d increments, each over the replicas that reached it (%d of %d reached every "
                "one); the largest spread (max - min) of a sigma component is %.4g N/m, %.3g of the stress scale "
                "%.4g N/m; summary: %s\n", rows, K - failed, K, spread, scale > 0.0 ? spread / scale : 0.0, scale,
                summary);
    if (failed)
        return sbc_fail(err, SBC_ERR_DIVERGED, "replicas: %d of %d replicas stopped (replica %d first; its message "
                        "is above); %s covers each increment over the replicas that reached it (column replicas)",
                        failed, K, first_failed, summary);
    return SBC_OK;
}
