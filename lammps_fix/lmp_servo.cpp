/* lmp_servo: the stock LAMMPS command line with fix servo_bc registered, for
   LAMMPS builds without the PLUGIN package (such as Debian's). */
#include "fix_servo_bc.h"
#include "fix_servo_bc_bonds.h"
#include "input.h"
#include "lammps.h"
#include "modify.h"

#include <mpi.h>

using namespace LAMMPS_NS;

static Fix *create_servo_bc(LAMMPS *lmp, int narg, char **arg)
{
  return new FixServoBC(lmp, narg, arg);
}

static Fix *create_servo_bc_bonds(LAMMPS *lmp, int narg, char **arg)
{
  return new FixServoBCBonds(lmp, narg, arg);
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  LAMMPS *lmp = new LAMMPS(argc, argv, MPI_COMM_WORLD);
  (*lmp->modify->fix_map)["servo_bc"] = &create_servo_bc;
  (*lmp->modify->fix_map)["servo_bc/bonds"] = &create_servo_bc_bonds;
  lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return 0;
}
