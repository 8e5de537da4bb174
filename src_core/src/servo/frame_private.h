/* Private: what the frame's files share (frame.c, frame_2d.c). */
#ifndef SBC_FRAME_PRIVATE_H
#define SBC_FRAME_PRIVATE_H

#include "sbc/frame.h"

/* Zeroes f and allocates its arrays for q positions of dimension dim (the
 * vectors' third slots 0); frees them and fails with SBC_ERR_NOMEM. */
sbc_status sbc_frame_alloc(sbc_frame *f, int dim, int q, sbc_error *err);

#endif
