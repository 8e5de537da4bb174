/* servo_bc: the time step's bounds (time_step.h). */
#include "sbc/time_step.h"
#include "update_rules.h"

#include <math.h>
#include <stdio.h>

sbc_status sbc_time_step_bound(double dt, double dtc, const char *formula, long max_relax_steps, sbc_error *err)
{
    if (!(dt > 0.0) || !isfinite(dt))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s (expected a finite time step > 0)", dt);
    if (dt > dtc)
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s exceeds the critical step %g s = %s; lower the "
                        "time step to %g s or less", dt, dtc, formula, SBC_TIME_STEP_FRACTION * dtc);
    if (dt > SBC_TIME_STEP_FRACTION * dtc * (1.0 + 1e-5)) /* a fraction rounded to 5 digits passes */
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s is %.3g of the critical step %g s = %s; "
                        "relaxations converge only up to %g of it (a particle with several contacts is stable only below "
                        "a fraction of a contact pair's step: 1/sqrt(2) with the four contacts of a square lattice; "
                        "docs/stability.md); lower the time step to %g s or less", dt, dt / dtc, dtc, formula,
                        SBC_TIME_STEP_FRACTION, SBC_TIME_STEP_FRACTION * dtc);
    if (dt * (double)max_relax_steps < dtc)
        return sbc_fail(err, SBC_ERR_INPUT,
                        "servo_bc: time step %g s: max_relax_steps %ld steps of it do not span one critical step %g s "
                        "= %s, so no relaxation could end; raise the time step or max_relax_steps",
                        dt, max_relax_steps, dtc, formula);
    return SBC_OK;
}

sbc_status sbc_time_step_check(double dt, double kn, double mass_min, long index, long max_relax_steps,
                               sbc_error *err)
{
    char formula[160];
    if (!(dt > 0.0) || !isfinite(dt))
        return sbc_fail(err, SBC_ERR_INPUT, "servo_bc: time step %g s (expected a finite time step > 0)", dt);
    if (!(kn > 0.0) || !(mass_min > 0.0))
        return SBC_OK;
    if (index >= 0)
        snprintf(formula, sizeof formula, "2 sqrt(M / (2 kn)) of particle %ld (mass %g kg) at kn %g N/m", index,
                 mass_min, kn);
    else
        snprintf(formula, sizeof formula, "2 sqrt(M / (2 kn)) of the lightest particle (mass %g kg) at kn %g N/m",
                 mass_min, kn);
    return sbc_time_step_bound(dt, 2.0 * sqrt(mass_min / (2.0 * kn)), formula, max_relax_steps, err);
}

int sbc_time_step_note(const sbc_settings *s, double dt, double dtc, char *out, size_t cap)
{
    const sbc_update_rule *rule = sbc_update_rule_of(s->update);
    if (!rule || !rule->scale_free_gains || !(dt > 0.0) || !(dt < SBC_TIME_STEP_SLOW * dtc) || cap == 0)
        return 0;
    snprintf(out, cap,
             "servo_bc: time step %g s is 1/%.0f of the critical step %g s: a relaxation's DEM steps grow about as "
             "1/dt for the same balance (docs/stability.md, \"Time step\"); %g s, 0.1 of the critical step, is as "
             "accurate and about %.0f times faster",
             dt, dtc / dt, dtc, 0.1 * dtc, 0.1 * dtc / dt);
    return 1;
}

int sbc_time_step_note_mass(const sbc_settings *s, double dt, double kn, double mass_min, char *out, size_t cap)
{
    if (!(kn > 0.0) || !(mass_min > 0.0))
        return 0;
    return sbc_time_step_note(s, dt, 2.0 * sqrt(mass_min / (2.0 * kn)), out, cap);
}
