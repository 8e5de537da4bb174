/* The mixed (D)-(P)-(T) grammar: which component of which edge is D, P or T
 * is data (keywords bottom/right/top/left), the prescribed stresses come
 * from `stress`, and contradictions are refused here, once, for every host. */
#include "settings_mixed.h"

#include <stdio.h>
#include <string.h>

static const char *const edge_names[4] = {"bottom", "right", "top", "left"};
static const char *const comp_names[2] = {"x", "y"};
static const char mode_letters[] = "DPT";

void sbc_mixed_default(sbc_settings *s)
{
    static const unsigned char layer[4][SBC_DIM_MAX] = {{SBC_MODE_D, SBC_MODE_D}, {SBC_MODE_P, SBC_MODE_P},
                                              {SBC_MODE_D, SBC_MODE_T}, {SBC_MODE_P, SBC_MODE_P}};
    memcpy(s->edge_mode, layer, sizeof layer);
    s->nstress = 0;
    s->stress_increments = 0;
}

int sbc_mixed_edge_index(const char *word)
{
    int e;
    for (e = 0; e < 4; ++e)
        if (strcmp(word, edge_names[e]) == 0)
            return e;
    return -1;
}

sbc_status sbc_mixed_parse_edge(sbc_settings *s, const char *edge, int nw, const char *const *w, int *used,
                                sbc_error *err)
{
    int e = sbc_mixed_edge_index(edge), c;
    *used = nw < 2 ? nw : 2;
    if (nw < 2)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword '%s': missing modes (expected '%s Mx My' with M = D, P or T)",
                        edge, edge);
    for (c = 0; c < 2; ++c) {
        const char *m = strchr(mode_letters, w[c][0]);
        if (!m || w[c][0] == '\0' || w[c][1] != '\0')
            return sbc_fail(err, SBC_ERR_INPUT, "keyword '%s': mode of component %s '%s' is not valid (expected D, P "
                            "or T)", edge, comp_names[c], w[c]);
        s->edge_mode[e][c] = (unsigned char)(m - mode_letters);
    }
    return SBC_OK;
}

sbc_status sbc_mixed_parse_stress(sbc_settings *s, int nw, const char *const *w, int *used, sbc_error *err)
{
    sbc_stress_spec *sp;
    long n;
    int k;
    *used = nw < 3 ? nw : 3;
    if (nw < 3)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': missing values (expected 'stress Pij VALUE N', e.g. "
                        "'stress P22 -1.05e6 6')");
    if (s->nstress == 4)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': more than four components");
    sp = &s->stress[s->nstress];
    if (w[0][0] != 'P' || w[0][1] < '1' || w[0][1] > '2' || w[0][2] < '1' || w[0][2] > '2' || w[0][3] != '\0')
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': component '%s' is not valid (expected P11, P12, P21 "
                        "or P22)", w[0]);
    sp->i = w[0][1] - '1';
    sp->j = w[0][2] - '1';
    for (k = 0; k < s->nstress; ++k)
        if (s->stress[k].i == sp->i && s->stress[k].j == sp->j)
            return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': component %s is given twice", w[0]);
    if (sbc_parse_real(w[1], "VALUE", &sp->value, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': %s value '%s' is not a number (N/m)", w[0], w[1]);
    if (sbc_parse_int(w[2], "N", 1, 100000000L, &n, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': increments '%s' is not valid (expected an integer >= "
                        "1)", w[2]);
    if (s->nstress > 0 && n != s->stress_increments)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': %s is applied in %ld increments, the stress before "
                        "in %d (all stress components share one stress stage)", w[0], n, s->stress_increments);
    s->stress_increments = (int)n;
    s->nstress++;
    return SBC_OK;
}

/* Normal direction of an edge: 1 (e2) for bottom/top, 0 (e1) for right/left. */
static int normal_of(int e) { return e == SBC_EDGE_BOTTOM || e == SBC_EDGE_TOP ? 1 : 0; }

sbc_status sbc_mixed_validate(const sbc_settings *s, sbc_error *err)
{
    char name[8];
    int e, c, k;
    for (e = 0; e < 4; ++e) {
        const unsigned char *m = s->edge_mode[e];
        if ((m[0] == SBC_MODE_P) != (m[1] == SBC_MODE_P))
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: %s %c %c: P holds for both components of an edge (eq. 19 "
                            "pairs positions and rotations), expected '%s P P'", edge_names[e],
                            mode_letters[m[0]], mode_letters[m[1]], edge_names[e]);
    }
    for (e = 0; e < 4; ++e) {
        const unsigned char *m = s->edge_mode[e], *o = s->edge_mode[(e + 2) % 4];
        if (m[0] == SBC_MODE_P && !(o[0] == SBC_MODE_P && o[1] == SBC_MODE_P))
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: %s is periodic (P P) but the opposite %s edge is %c %c: "
                            "periodic edges come in pairs", edge_names[e], edge_names[(e + 2) % 4],
                            mode_letters[o[0]], mode_letters[o[1]]);
        for (c = 0; c < 2; ++c) {
            int found = 0;
            if (m[c] != SBC_MODE_T)
                continue;
            for (k = 0; k < s->nstress; ++k)
                found |= s->stress[k].i == c && s->stress[k].j == normal_of(e);
            if (!found)
                return sbc_fail(err, SBC_ERR_INPUT, "mixed: component %s of the %s edge is under T but no 'stress "
                                "P%d%d VALUE N' prescribes its traction (eq. 43)", comp_names[c], edge_names[e],
                                c + 1, normal_of(e) + 1);
            for (k = 0; k < 2; ++k) {
                double want = k == c ? 1.0 : 0.0;
                if (s->F[SBC_IJ(c, k)] != want)
                    return sbc_fail(err, SBC_ERR_INPUT, "mixed: keyword 'F' prescribes %s = %g, but component %s of the "
                                    "%s edge is under T, so %s is a result (eq. 45): leave row %d of F at the identity",
                                    sbc_tensor_component_name("F", c, k, name), s->F[SBC_IJ(c, k)], comp_names[c],
                                    edge_names[e], name, c + 1);
            }
        }
    }
    for (k = 0; k < s->nstress; ++k) {
        int i = s->stress[k].i, j = s->stress[k].j, found = 0;
        for (e = 0; e < 4; ++e)
            found |= normal_of(e) == j && s->edge_mode[e][i] == SBC_MODE_T;
        if (!found)
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: 'stress P%d%d' is prescribed, but no edge with normal e%d has "
                            "component %s under T (the stress would be both prescribed and free of any traction "
                            "control); set e.g. '%s %s'",
                            i + 1, j + 1, j + 1, comp_names[i], j ? "top" : "right", i ? "D T" : "T D");
    }
    return SBC_OK;
}
