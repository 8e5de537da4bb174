/* servo_bc: the contact network of an engine state as an SVG picture
 * (paper Figs. 8 and 12): discs as circles (frame particles shaded), one
 * line between the centres per force-carrying pair, its width proportional
 * to |fn|; frictional contacts blue, intact cohesive bonds red (dashed when
 * in tension). */
#ifndef SBC_NETWORK_H
#define SBC_NETWORK_H

#include "sbc/engine.h"

sbc_status sbc_network_svg(const char *path, const char *title, const sbc_engine_view *view, sbc_error *err);

#endif
