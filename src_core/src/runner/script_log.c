/* The runner's log lines that the disc and sphere runs share. */
#include "script_state.h"

#include <stdio.h>

void sbc_script_tally_line(const script *s, const sbc_statics_tally *t)
{
    char retried[96] = "";
    if (t->retried)
        snprintf(retried, sizeof retried, " (%d stalled and converged again, the rotations balanced one by one)",
                 t->retried);
    char broken[64] = "";
    if (t->broken)
        snprintf(broken, sizeof broken, ", %d bonds broken (the worst first)", t->broken);
    fprintf(s->log, "  interior newton: %d solves%s, %ld iterations%s, last residual %.2e, %d dofs held%s%s\n",
            t->solves, retried, t->iterations, broken, t->residual, t->mechanisms,
            t->unconverged ? "; the dynamic relaxation finished an unconverged solve: " : "",
            t->unconverged ? t->why : "");
}
