/* The runner's keyword tangent (docs/fe2.md, "The runner's tangent file"):
 * the tangent C = dP/dF of the aggregate at every converged increment, as
 * the material point computes it, into a CSV of dim^4 columns. */
#include "script_state.h"

#include <math.h>
#include <string.h>

#include "sbc/embedded/output_file.h"
#include "sbc/tensor.h"

/* central differences of this step on each F_kl (docs/fe2.md) */
#define PERTURBATION_STEP 1e-6
/* the file in messages; a row: 81 values of 25 characters at most */
#define WHAT "servo_bc keyword 'tangent': file"
#define ROW_CHARS (16 + 81 * 26)

sbc_status sbc_script_tangent_open(const script *s, int dim, sbc_script_tangent *t, sbc_error *err)
{
    char line[ROW_CHARS];
    int i, j, k, l, n;
    memset(t, 0, sizeof *t);
    t->dim = dim;
    if (s->settings.tangent == SBC_TANGENT_NONE)
        return SBC_OK;
    if (s->settings.bc == SBC_BC_MIXED)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc (line %d): keyword 'tangent': the condition is mixed; the "
                        "tangents are those of (D), (P) and (T) in this version", s->servo_line);
    if (s->cohesive && s->settings.tangent == SBC_TANGENT_AFFINE)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc (line %d): keyword 'tangent': affine sums the contacts of "
                        "eq. 6 alone, and the contacts are cohesive (eqs. 7-8; expected condensed or perturbation)",
                        s->servo_line);
    if (s->check) /* probed with the other outputs */
        return SBC_OK;
    if (!(t->fp = sbc_output_open(s->settings.tangent_file, SBC_OUTPUT_RESULTS, "servo_bc keyword 'tangent'", err)))
        return err->status;
    n = snprintf(line, sizeof line, "increment");
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j)
            for (k = 0; k < dim; ++k)
                for (l = 0; l < dim; ++l)
                    n += snprintf(line + n, sizeof line - (size_t)n, ",C%d%d%d%d", i + 1, j + 1, k + 1, l + 1);
    line[n++] = '\n';
    return sbc_output_append(t->fp, line, (size_t)n, s->settings.tangent_file, WHAT, "the header", err);
}

sbc_status sbc_script_tangent_row(const script *s, sbc_script_tangent *t, const sbc_aggregate *a,
                                  const sbc_controller *ctl, const sbc_fire_state *fire, const sbc_result *row,
                                  sbc_error *err)
{
    const int dim = t->dim;
    double C[81], norm = 0.0;
    char line[ROW_CHARS], which[64];
    int mechanisms = 0, i, j, k, l, n;
    sbc_status st;
    if (!t->fp)
        return SBC_OK;
    switch (s->settings.tangent) {
    case SBC_TANGENT_AFFINE:
        st = sbc_aggregate_affine(a, row->F, C, err);
        break;
    case SBC_TANGENT_CONDENSED:
        st = sbc_aggregate_condensed(a, NULL, C, &mechanisms, err);
        break;
    default:
        st = sbc_aggregate_perturbation(a, ctl, fire, PERTURBATION_STEP, C, err);
        break;
    }
    if (st != SBC_OK) {
        char message[SBC_ERROR_LEN];
        snprintf(message, sizeof message, "%s", err->message);
        return sbc_fail(err, st, "servo_bc keyword 'tangent' (%s), increment %d: %s",
                        sbc_tangent_name(s->settings.tangent), row->increment, message);
    }
    n = snprintf(line, sizeof line, "%d", row->increment);
    for (i = 0; i < dim; ++i)
        for (j = 0; j < dim; ++j)
            for (k = 0; k < dim; ++k)
                for (l = 0; l < dim; ++l) {
                    const double c = C[9 * SBC_IJ(i, j) + SBC_IJ(k, l)];
                    n += snprintf(line + n, sizeof line - (size_t)n, ",%.17g", c);
                    norm += c * c;
                }
    line[n++] = '\n';
    snprintf(which, sizeof which, "the row of increment %d", row->increment);
    if (sbc_output_append(t->fp, line, (size_t)n, s->settings.tangent_file, WHAT, which, err) != SBC_OK)
        return err->status;
    if (s->log) {
        fprintf(s->log, "  tangent %s: C1111 %.6g, |C| %.6g", sbc_tangent_name(s->settings.tangent), C[0],
                sqrt(norm));
        if (s->settings.tangent == SBC_TANGENT_CONDENSED)
            fprintf(s->log, ", %d mechanisms", mechanisms);
        fputc('\n', s->log);
    }
    return SBC_OK;
}

void sbc_script_tangent_close(sbc_script_tangent *t)
{
    if (t->fp)
        fclose(t->fp);
    t->fp = NULL;
}
