/* fix servo_bc and fix servo_bc/bonds as a LAMMPS plugin: `plugin load
   servo_bc_plugin.so` in LAMMPS builds with the PLUGIN package. */
#include "lammpsplugin.h"
#include "version.h"

#include "fix_servo_bc.h"
#include "fix_servo_bc_bonds.h"

using namespace LAMMPS_NS;

static Fix *servo_bc_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixServoBC(lmp, argc, argv);
}

static Fix *servo_bc_bonds_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixServoBCBonds(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  lammpsplugin_regfunc register_plugin = (lammpsplugin_regfunc) regfunc;
  plugin.version = LAMMPS_VERSION;
  plugin.style = "fix";
  plugin.name = "servo_bc";
  plugin.info = "fix servo_bc: micro-scale boundary conditions (D), (P), (T) for particle aggregates";
  plugin.author = "servo_bc developers";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &servo_bc_creator;
  plugin.handle = handle;
  (*register_plugin)(&plugin, lmp);
  plugin.name = "servo_bc/bonds";
  plugin.info = "fix servo_bc/bonds: bonded particles (Timoshenko beams, parallel bonds, cohesive bonds)";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &servo_bc_bonds_creator;
  (*register_plugin)(&plugin, lmp);
}
