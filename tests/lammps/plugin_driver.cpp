/* The plugin route without a PLUGIN-enabled LAMMPS (Debian has none): dlopen
   the plugin, call its exported lammpsplugin_init with a registration function
   that does what `plugin load` does for a fix style (insert the creator into
   Modify::fix_map), then run the input deck with the stock LAMMPS library.
     plugin_driver PLUGIN.so [LAMMPS arguments]                                */
#include "input.h"
#include "lammps.h"
#include "lammpsplugin.h"
#include "modify.h"

#include <cstdio>
#include <cstring>
#include <dlfcn.h>
#include <mpi.h>

using namespace LAMMPS_NS;

static int registered = 0;

static void register_plugin(lammpsplugin_t *p, void *ptr)
{
  LAMMPS *lmp = (LAMMPS *) ptr;
  if (std::strcmp(p->style, "fix") != 0 || std::strncmp(p->name, "servo_bc", 8) != 0 || !p->creator.v2) {
    std::fprintf(stderr, "plugin_driver: unexpected plugin %s %s\n", p->style, p->name);
    return;
  }
  (*lmp->modify->fix_map)[p->name] = (Modify::FixCreator) p->creator.v2;
  std::printf("plugin_driver: registered %s style %s (%s, LAMMPS %s)\n", p->style, p->name, p->info, p->version);
  registered = 1;
}

int main(int argc, char **argv)
{
  if (argc < 2) {
    std::fprintf(stderr, "usage: plugin_driver PLUGIN.so [LAMMPS arguments]\n");
    return 2;
  }
  MPI_Init(&argc, &argv);
  void *handle = dlopen(argv[1], RTLD_NOW | RTLD_GLOBAL);
  if (!handle) {
    std::fprintf(stderr, "plugin_driver: %s\n", dlerror());
    return 1;
  }
  auto init = (lammpsplugin_initfunc) dlsym(handle, "lammpsplugin_init");
  if (!init) {
    std::fprintf(stderr, "plugin_driver: no lammpsplugin_init in %s\n", argv[1]);
    return 1;
  }
  argv[1] = argv[0];
  LAMMPS *lmp = new LAMMPS(argc - 1, argv + 1, MPI_COMM_WORLD);
  init((void *) lmp, handle, (void *) &register_plugin);
  if (registered) lmp->input->file();
  delete lmp;
  MPI_Finalize();
  return registered ? 0 : 1;
}
