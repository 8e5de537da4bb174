/* servo_bc: the contact network of an engine state as an SVG picture
 * (paper Figs. 8 and 12): discs as circles (frame particles shaded), one
 * line between the centres per force-carrying pair, its width proportional
 * to |fn|; frictional contacts blue, intact cohesive bonds red (dashed when
 * in tension). With a frame (NULL: none), the polygon of the frame's
 * centres in frame order is drawn over it, and an interior disc whose centre
 * has left that polygon (confine.h) is filled orange: the picture of a run
 * that stopped on an escaped disc shows where the frame opened. */
#ifndef SBC_NETWORK_H
#define SBC_NETWORK_H

#include "sbc/embedded/engine.h"
#include "sbc/frame.h"

#ifdef __cplusplus
extern "C" {
#endif

sbc_status sbc_network_svg(const char *path, const char *title, const sbc_engine_view *view, const sbc_frame *frame,
                           sbc_error *err);

#ifdef __cplusplus
}
#endif

#endif
