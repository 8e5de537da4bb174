/* Private: the mixed (D)-(P)-(T) part of the servo_bc grammar (Sect. 5). */
#ifndef SBC_SETTINGS_MIXED_H
#define SBC_SETTINGS_MIXED_H

#include "sbc/settings.h"

/* The paper's layer: bottom D D, right P P, top D T, left P P; no stress. */
void sbc_mixed_default(sbc_settings *s);

/* SBC_EDGE_* of "bottom", "right", "top", "left"; -1 otherwise. */
int sbc_mixed_edge_index(const char *word);

/* "EDGE Mx My" and "stress Pij VALUE N": the words after the keyword;
 * *used is set to the number of words consumed. */
sbc_status sbc_mixed_parse_edge(sbc_settings *s, const char *edge, int nw, const char *const *w, int *used,
                                sbc_error *err);
sbc_status sbc_mixed_parse_stress(sbc_settings *s, int nw, const char *const *w, int *used, sbc_error *err);

/* Refuses contradictory specifications (see docs/servo_bc.md, "mixed"). */
sbc_status sbc_mixed_validate(const sbc_settings *s, sbc_error *err);

#endif
