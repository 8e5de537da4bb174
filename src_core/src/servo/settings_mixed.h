/* Private: the mixed (D)-(P)-(T) part of the servo_bc grammar (Sect. 5). */
#ifndef SBC_SETTINGS_MIXED_H
#define SBC_SETTINGS_MIXED_H

#include "sbc/settings.h"

/* The paper's layer in 2D (bottom D D, right P P, top D T, left P P; the
 * faces of dimension 3 likewise for the 3D layer, applied by
 * sbc_mixed_validate to the faces the words leave out); no stress. */
void sbc_mixed_default(sbc_settings *s);

/* The face index of a face keyword: "bottom", "right", "top", "left" (2D
 * edges) or "xlo" ... "zhi" (3D faces); -1 otherwise. */
int sbc_mixed_face_index(const char *word);

/* "FACE Mx My" (2D edge) or "FACE Mx My Mz" (3D face) and "stress Pij VALUE
 * N": the words after the keyword; *used is set to the number consumed. */
sbc_status sbc_mixed_parse_face(sbc_settings *s, const char *face, int nw, const char *const *w, int *used,
                                sbc_error *err);
sbc_status sbc_mixed_parse_stress(sbc_settings *s, int nw, const char *const *w, int *used, sbc_error *err);

/* The 3D layer on the faces the words leave out when s->dim is 3; then
 * refuses contradictory specifications (see docs/servo_bc.md, "mixed"). */
sbc_status sbc_mixed_validate(sbc_settings *s, sbc_error *err);

#endif
