/* servo_bc: FIRE's velocity mix with the host's fixed time step (fire_damping.h). */
#include "sbc/fire_damping.h"

#include <math.h>

#define FIRE_ALPHA_START 0.1 /* Bitzek et al. 2006, a_start */
#define FIRE_F_ALPHA 0.99    /* f_alpha */
#define FIRE_N_MIN 5         /* N_min */

void sbc_fire_start(sbc_fire_state *s)
{
    s->alpha = FIRE_ALPHA_START;
    s->positive = 0;
}

sbc_fire_mix sbc_fire_step(sbc_fire_state *s, const double sums[SBC_FIRE_SUMS])
{
    sbc_fire_mix m = {1.0, 0.0, 0.0, 0.0};
    if (!(sums[SBC_FIRE_POWER] > 0.0)) {
        s->alpha = FIRE_ALPHA_START;
        s->positive = 0;
        m.keep = 0.0;
        m.stop = 1.0;
        return m;
    }
    m.keep = 1.0 - s->alpha;
    if (sums[SBC_FIRE_FF] > 0.0)
        m.push = s->alpha * sqrt(sums[SBC_FIRE_VV] / sums[SBC_FIRE_FF]);
    if (sums[SBC_FIRE_MM] > 0.0)
        m.spin = s->alpha * sqrt(sums[SBC_FIRE_WW] / sums[SBC_FIRE_MM]);
    if (++s->positive > FIRE_N_MIN)
        s->alpha *= FIRE_F_ALPHA;
    return m;
}
