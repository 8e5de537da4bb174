/* servo_bc: the time step's bounds (time_step.h). */
#include "sbc/time_step.h"

#include <math.h>
#include <stdio.h>

sbc_status sbc_time_step_check(double dt, double kn, double mass_min, long index, long max_relax_steps,
                               sbc_error *err)
{
    char who[96] = "";
    double dtc;
    if (!(dt > 0.0) || !isfinite(dt))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s (expected a finite time step > 0)", dt);
    if (!(kn > 0.0) || !(mass_min > 0.0))
        return SBC_OK;
    dtc = 2.0 * sqrt(mass_min / (2.0 * kn));
    if (index >= 0)
        snprintf(who, sizeof who, " of particle %ld (mass %g kg)", index, mass_min);
    else
        snprintf(who, sizeof who, " of the lightest particle (mass %g kg)", mass_min);
    if (dt > dtc)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "servo_bc: time step %g s exceeds the critical step %g s = 2 sqrt(M / (2 kn))%s at kn %g N/m; "
                        "lower the time step, or check that mass",
                        dt, dtc, who, kn);
    if (dt * (double)max_relax_steps < dtc)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "servo_bc: time step %g s: max_relax_steps %ld steps of it do not span one critical step %g s "
                        "= 2 sqrt(M / (2 kn))%s, so no relaxation could end; raise the time step or max_relax_steps",
                        dt, max_relax_steps, dtc, who);
    return SBC_OK;
}
