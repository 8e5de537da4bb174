/* Writes a valid restart input for fuzz_restart.c (the case of
 * restart_case.h, saved in the middle of increment 1's servo iterations), so
 * that the corpus follows the format of this version of the core.
 *   restart_seed FILE */
#include "restart_case.h"

#include "sbc/controller.h"

int main(int argc, char **argv)
{
    sbc_packing p;
    sbc_frame f;
    sbc_settings s = restart_case_settings();
    sbc_error err;
    sbc_engine *e = restart_case_engine(&p, &f);
    sbc_controller *c;
    double mass[16], *state, len;
    size_t nf, nc;
    long step;
    int corrections = 0;
    FILE *fp;
    if (argc != 2 || f.n > 16)
        return 2;
    sbc_engine_frame_masses(e, mass);
    if (!(c = sbc_controller_create(&f, &s, mass, RESTART_CASE_DT, sbc_engine_def_default().law.kn, &err)))
        return 1;
    for (step = 0; step < 200000 && corrections < 3; ++step) {
        sbc_snapshot snap;
        sbc_commands cmd;
        sbc_engine_step(e, &err);
        sbc_engine_snapshot(e, &snap);
        if (sbc_controller_step(c, &snap, &err) == SBC_EVENT_CORRECTED && sbc_controller_increment(c) == 1)
            ++corrections;
        cmd = sbc_controller_commands(c);
        sbc_engine_move_frame(e, &cmd);
    }
    nf = sbc_frame_state_size(&f);
    nc = sbc_controller_state_size(c);
    if (corrections < 3 || !(state = malloc(sizeof(double) * (nf + nc))) || !(fp = fopen(argv[1], "wb")))
        return 1;
    sbc_frame_save(&f, state);
    sbc_controller_save(c, state + nf);
    len = (double)nf;
    if (fwrite(&len, sizeof len, 1, fp) != 1 || fwrite(state, sizeof(double), nf + nc, fp) != nf + nc || fclose(fp) != 0)
        return 1;
    free(state);
    sbc_controller_free(c);
    sbc_engine_free(e);
    sbc_frame_free(&f);
    sbc_packing_free(&p);
    return 0;
}
