/* servo-bc --decks: the case of a script written for every host (decks.c),
 * the writer sbc_script_decks_file calls at the script's 'run'. */
#ifndef SBC_RUNNER_DECKS_H
#define SBC_RUNNER_DECKS_H

#include "sbc/embedded/script.h"

/* Writes into the folder dir the packing in every host's format and
 * embedded.sbc, lammps.in, liggghts.in, yade.py for the case s (sbc_script_decks_fn). */
sbc_status sbc_runner_write_decks(sbc_script_case *s, const char *dir, sbc_error *err);

#endif
