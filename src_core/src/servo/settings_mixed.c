/* The mixed (D)-(P)-(T) grammar: which component of which face is D, P or T
 * is data (keywords bottom/right/top/left for the 2D edges, xlo ... zhi for
 * the 3D faces), the prescribed stresses come from `stress`, and
 * contradictions are refused here, once, for every host. */
#include "settings_mixed.h"

#include <stdio.h>
#include <string.h>

static const char *const face_names[SBC_FACES_MAX] = {"xlo", "xhi", "ylo", "yhi", "zlo", "zhi"};
static const char *const edge_names[4] = {"left", "right", "bottom", "top"}; /* faces 0-3 in 2D */
static const char *const comp_names[3] = {"x", "y", "z"};
static const char mode_letters[] = "DPT";

/* the face's keyword in dimension dim */
static const char *face_label(int dim, int f) { return dim == 2 ? edge_names[f] : face_names[f]; }

/* the modes of a face as words, "D T" (2D) or "P P P" (3D) */
static const char *modes_text(int dim, const unsigned char *m, char out[8])
{
    snprintf(out, 8, dim == 2 ? "%c %c" : "%c %c %c", mode_letters[m[0]], mode_letters[m[1]], mode_letters[m[2]]);
    return out;
}

/* the axis normal to face f */
static int normal_of(int f) { return f / 2; }

/* the layer: the faces normal to the last axis are the support (low, D)
   and the loaded top (high, T along the normal); the others periodic */
static void layer_face(int dim, int f, unsigned char mode[SBC_DIM_MAX])
{
    int c;
    for (c = 0; c < SBC_DIM_MAX; ++c)
        mode[c] = normal_of(f) != dim - 1 ? SBC_MODE_P : (f % 2 == 1 && c == dim - 1 ? SBC_MODE_T : SBC_MODE_D);
}

void sbc_mixed_default(sbc_settings *s)
{
    int f;
    memset(s->face_mode, SBC_MODE_D, sizeof s->face_mode);
    for (f = 0; f < 4; ++f)
        layer_face(2, f, s->face_mode[f]);
    s->face_given = s->edge_given = 0;
    s->nstress = 0;
    s->stress_increments = 0;
}

int sbc_mixed_face_index(const char *word)
{
    int f;
    for (f = 0; f < SBC_FACES_MAX; ++f)
        if (strcmp(word, face_names[f]) == 0)
            return f;
    for (f = 0; f < 4; ++f)
        if (strcmp(word, edge_names[f]) == 0)
            return f;
    return -1;
}

sbc_status sbc_mixed_parse_face(sbc_settings *s, const char *face, int nw, const char *const *w, int *used,
                                sbc_error *err)
{
    const int f = sbc_mixed_face_index(face), n = strcmp(face, face_names[f]) == 0 ? 3 : 2;
    int c;
    *used = nw < n ? nw : n;
    if (nw < n)
        return sbc_fail(err, SBC_ERR_INPUT, n == 2 ? "keyword '%s': missing modes (expected '%s Mx My' with M = D, P "
                                                     "or T)"
                                                   : "keyword '%s': missing modes (expected '%s Mx My Mz' with M = "
                                                     "D, P or T)",
                        face, face);
    for (c = 0; c < n; ++c) {
        const char *m = strchr(mode_letters, w[c][0]);
        if (!m || w[c][0] == '\0' || w[c][1] != '\0')
            return sbc_fail(err, SBC_ERR_INPUT, "keyword '%s': mode of component %s '%s' is not valid (expected D, P "
                            "or T)", face, comp_names[c], w[c]);
        s->face_mode[f][c] = (unsigned char)(m - mode_letters);
    }
    s->face_given |= (unsigned char)(1u << f);
    if (n == 2)
        s->edge_given |= (unsigned char)(1u << f);
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
    if (s->nstress == 9)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': more than nine components");
    sp = &s->stress[s->nstress];
    if (w[0][0] != 'P' || w[0][1] < '1' || w[0][1] > '3' || w[0][2] < '1' || w[0][2] > '3' || w[0][3] != '\0')
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': component '%s' is not valid (expected P11, P12, P21 "
                        "or P22; P11 ... P33 in 3D)", w[0]);
    sp->i = w[0][1] - '1';
    sp->j = w[0][2] - '1';
    for (k = 0; k < s->nstress; ++k)
        if (s->stress[k].i == sp->i && s->stress[k].j == sp->j)
            return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': component %s is given twice", w[0]);
    if (sbc_parse_real(w[1], "VALUE", &sp->value, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': %s value '%s' is not a number (N/m)", w[0], w[1]);
    if (sbc_parse_int(w[2], "N", 0, 100000000L, &n, NULL) != SBC_OK)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': increments '%s' is not valid (expected an integer >= "
                        "0; 0 holds the stress from increment 0, without a stress stage)", w[2]);
    if (s->nstress > 0 && n != s->stress_increments)
        return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': %s is applied in %ld increments, the stress before "
                        "in %d (all stress components share one stress stage)", w[0], n, s->stress_increments);
    s->stress_increments = (int)n;
    s->nstress++;
    return SBC_OK;
}

/* the words' faces hold to the dimension: 2D edge keywords in 2D, 3D face
   keywords in 3D, stress components within dim */
static sbc_status faces_of_dimension(const sbc_settings *s, sbc_error *err)
{
    int f, k;
    for (f = 0; f < SBC_FACES_MAX; ++f) {
        if (!(s->face_given >> f & 1))
            continue;
        if (s->dim == 2 && f >= 4)
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: keyword '%s' names a 3D face, but the words are 2D (F with "
                            "nine values makes them 3D; the 2D edges are bottom, right, top, left)", face_names[f]);
        if (s->dim == 3 && (s->edge_given >> f & 1))
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: keyword '%s' names a 2D edge, but the words are 3D (F has nine "
                            "values); the 3D faces are xlo, xhi, ylo, yhi, zlo, zhi, each with three modes", edge_names[f]);
    }
    for (k = 0; k < s->nstress; ++k)
        if (s->stress[k].i >= s->dim || s->stress[k].j >= s->dim)
            return sbc_fail(err, SBC_ERR_INPUT, "keyword 'stress': component 'P%d%d' is not valid in 2D (expected "
                            "P11, P12, P21 or P22; F with nine values makes the words 3D)",
                            s->stress[k].i + 1, s->stress[k].j + 1);
    return SBC_OK;
}

sbc_status sbc_mixed_validate(sbc_settings *s, sbc_error *err)
{
    const int dim = s->dim, nf = 2 * dim;
    char name[8], text[8];
    int f, c, k;
    if (faces_of_dimension(s, err) != SBC_OK)
        return err->status;
    if (dim == 3)
        for (f = 0; f < nf; ++f)
            if (!(s->face_given >> f & 1))
                layer_face(3, f, s->face_mode[f]);
    for (f = 0; f < nf; ++f) {
        const unsigned char *m = s->face_mode[f];
        int any_p = 0, all_p = 1;
        for (c = 0; c < dim; ++c) {
            any_p |= m[c] == SBC_MODE_P;
            all_p &= m[c] == SBC_MODE_P;
        }
        if (any_p && !all_p)
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: %s %s: P holds for %s components of %s (eq. 19 pairs "
                            "positions and rotations), expected '%s %s'", face_label(dim, f), modes_text(dim, m, text),
                            dim == 2 ? "both" : "every", dim == 2 ? "an edge" : "a face", face_label(dim, f),
                            dim == 2 ? "P P" : "P P P");
    }
    for (f = 0; f < nf; ++f) {
        const unsigned char *m = s->face_mode[f], *o = s->face_mode[f ^ 1];
        if (m[0] == SBC_MODE_P && o[0] != SBC_MODE_P)
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: %s is periodic (%s) but the opposite %s %s is %s: periodic "
                            "%s come in pairs", face_label(dim, f), dim == 2 ? "P P" : "P P P", face_label(dim, f ^ 1),
                            dim == 2 ? "edge" : "face", modes_text(dim, o, text), dim == 2 ? "edges" : "faces");
        for (c = 0; c < dim; ++c) {
            int found = 0;
            if (m[c] != SBC_MODE_T)
                continue;
            for (k = 0; k < s->nstress; ++k)
                found |= s->stress[k].i == c && s->stress[k].j == normal_of(f);
            if (!found)
                return sbc_fail(err, SBC_ERR_INPUT, "mixed: component %s of the %s %s is under T but no 'stress "
                                "P%d%d VALUE N' prescribes its traction (eq. 43)", comp_names[c], face_label(dim, f),
                                dim == 2 ? "edge" : "face", c + 1, normal_of(f) + 1);
            for (k = 0; k < dim; ++k) {
                double want = k == c ? 1.0 : 0.0;
                if (s->F[SBC_IJ(c, k)] != want)
                    return sbc_fail(err, SBC_ERR_INPUT, "mixed: keyword 'F' prescribes %s = %g, but component %s of the "
                                    "%s %s is under T, so %s is a result (eq. 45): leave row %d of F at the identity",
                                    sbc_tensor_component_name("F", c, k, name), s->F[SBC_IJ(c, k)], comp_names[c],
                                    face_label(dim, f), dim == 2 ? "edge" : "face", name, c + 1);
            }
        }
    }
    for (k = 0; k < s->nstress; ++k) {
        int i = s->stress[k].i, j = s->stress[k].j, found = 0;
        for (f = 0; f < nf; ++f)
            found |= normal_of(f) == j && s->face_mode[f][i] == SBC_MODE_T;
        if (!found) {
            if (dim == 2)
                return sbc_fail(err, SBC_ERR_INPUT, "mixed: 'stress P%d%d' is prescribed, but no edge with normal e%d "
                                "has component %s under T (the stress would be both prescribed and free of any "
                                "traction control); set e.g. '%s %s'",
                                i + 1, j + 1, j + 1, comp_names[i], j ? "top" : "right", i ? "D T" : "T D");
            return sbc_fail(err, SBC_ERR_INPUT, "mixed: 'stress P%d%d' is prescribed, but no face with normal e%d has "
                            "component %s under T (the stress would be both prescribed and free of any traction "
                            "control); set e.g. '%s %s %s %s'", i + 1, j + 1, j + 1, comp_names[i], face_names[2 * j + 1],
                            i == 0 ? "T" : "D", i == 1 ? "T" : "D", i == 2 ? "T" : "D");
        }
    }
    return SBC_OK;
}
