/* The runner's log lines that the disc and sphere runs share. */
#include "script_state.h"

#include <stdio.h>

void sbc_script_tally_line(const script *s, const sbc_statics_tally *t)
{
    fprintf(s->log, "  interior newton: %d solves, %ld iterations, last residual %.2e, %d dofs held%s%s\n",
            t->solves, t->iterations, t->residual, t->mechanisms,
            t->unconverged ? "; the dynamic relaxation finished an unconverged solve: " : "",
            t->unconverged ? t->why : "");
}
