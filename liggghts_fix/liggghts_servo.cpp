/* liggghts_servo: the stock LIGGGHTS command line with fix servo_bc and
   fix servo_bc/bonds registered, built against the Debian LIGGGHTS library without touching it.

   LIGGGHTS 3.8 keeps Modify::fix_map private. An explicit template
   instantiation may name a private member (C++11 [temp.explicit]/12: the usual
   access checking does not apply to its arguments); the instantiated template
   hands the pointer to member out through a friend function. */
#include "fix_servo_bc.h"
#include "fix_servo_bc_bonds.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <cstdio>
#include <map>
#include <mpi.h>
#include <string>

using namespace LAMMPS_NS;

namespace {
typedef Fix *(*FixCreator)(LAMMPS *, int, char **);
typedef std::map<std::string, FixCreator> *Modify::*FixMapMember;

struct FixMap {
  friend FixMapMember member(FixMap);
};
template <FixMapMember M> struct Expose {
  friend FixMapMember member(FixMap) { return M; }
};
template struct Expose<&Modify::fix_map>;

Fix *create_servo_bc(LAMMPS *lmp, int narg, char **arg)
{
  return new FixServoBC(lmp, narg, arg);
}

Fix *create_servo_bc_bonds(LAMMPS *lmp, int narg, char **arg)
{
  return new FixServoBCBonds(lmp, narg, arg);
}
}    // namespace

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  // LIGGGHTS prints an error to stdout and calls MPI_Abort: on a pipe, a
  // block-buffered stdout lost the message (LIGGGHTS 3.8, tried)
  setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  LAMMPS *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  (*(lmp->modify->*member(FixMap())))["servo_bc"] = &create_servo_bc;
  (*(lmp->modify->*member(FixMap())))["servo_bc/bonds"] = &create_servo_bc_bonds;
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
