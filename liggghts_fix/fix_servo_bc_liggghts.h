/* What fix servo_bc (lammps_fix/fix_servo_bc.cpp, one source for LAMMPS and
   LIGGGHTS, compiled with -DSERVO_BC_LIGGGHTS) takes from LIGGGHTS 3.8 where
   LAMMPS differs; the LAMMPS side is lammps_fix/fix_servo_bc_lammps.h.
   - contact law: pair_style gran model hooke/stiffness tangential history
     reads kn and kt from fix property/global, and keeps the shear history in
     the granular history list at an offset among the models' history values;
   - inertia: fix nve/sphere keeps the sphere's 2/5 m r^2 in 2d;
   - end of run: LIGGGHTS 3.8 has no timeout, so a run cannot be ended early;
     the fix goes idle and the script loops on f_ID[18] (docs/liggghts). */
#ifndef SERVO_BC_HOST_LIGGGHTS_H
#define SERVO_BC_HOST_LIGGGHTS_H

#include "atom.h"
#include "fix_property_global.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"
#include "neigh_list.h"
#include "pair_gran.h"

#include <string>

namespace LAMMPS_NS {
namespace servo_bc_host {

// I = inertia m r^2: LIGGGHTS integrates 2d particles as spheres
constexpr double inertia = 0.4;
// the integrator's words for that (error messages)
constexpr const char *disc_keyword = "";
// Error::one writes to the screen only: under -screen none its message is lost unless the fix logs it
constexpr bool one_writes_log = false;
constexpr const char *contact_law =
    "pair_style gran model hooke/stiffness tangential history absolute_damping on, with fix property/global "
    "kn, kt, gamman_abs, gammat_abs and coefficientFriction";

// history_arg (the names of the models' history values) is protected in
// PairGran; a derived class may name it
struct GranAccess : PairGran {
  static int offset_of(PairGran *p, const char *name)
  {
    const auto &args = p->*(&GranAccess::history_arg);
    for (size_t k = 0; k < args.size(); k++)
      if (args[k].name == name) return (int) k;
    return -1;
  }
};

/* eq. 6 as pair gran hooke/stiffness holds it: kn, kt (N/m) and, per neighbour
   jj of atom i, the elastic shear displacement at history(i)[stride*jj + offset] */
struct ContactLaw {
  double kn = 0.0, kt = 0.0;
  int stride = 0, offset = 0;
  PairGran *pair = nullptr;

  // "" when found, else what is missing
  std::string attach(LAMMPS *lmp)
  {
    const std::string need = std::string("requires ") + contact_law + " (the paper's contact law, eq. 6)";
    pair = dynamic_cast<PairGran *>(lmp->force->pair_match("gran", 1));
    if (!pair) return need;
    offset = GranAccess::offset_of(pair, "shearx");
    if (offset < 0) return need + "; this pair style keeps no tangential history";
    stride = pair->dnum();
    const int nt = lmp->atom->ntypes;
    std::string why = stiffness(lmp, "kn", nt, kn);
    if (why.empty()) why = stiffness(lmp, "kt", nt, kt);
    // eq. 6 has no dashpot: the damping of the relaxation is the fix's
    for (const char *name : {"gamman_abs", "gammat_abs"}) {
      double gamma = 0.0;
      if (why.empty()) why = stiffness(lmp, name, nt, gamma);
      if (why.empty() && gamma != 0.0)
        why = std::string("fix property/global ") + name + " is " + std::to_string(gamma) +
              "; eq. 6 has no dashpots (set it to 0)";
    }
    return why.empty() ? why : need + "; " + why;
  }
  NeighList *list() const { return pair->list; }
  double **history() const { return pair->listgranhistory ? pair->listgranhistory->firstdouble : nullptr; }

 private:
  // the single value of a peratomtypepair property, N/m
  static std::string stiffness(LAMMPS *lmp, const char *name, int nt, double &k)
  {
    auto *fp = static_cast<FixPropertyGlobal *>(
        lmp->modify->find_fix_property(name, "property/global", "peratomtypepair", nt, nt, "fix servo_bc", false));
    if (!fp) return std::string("no fix property/global ") + name + " peratomtypepair";
    k = fp->compute_array(0, 0) / lmp->force->nktv2p;
    for (int a = 0; a < nt; a++)
      for (int b = 0; b < nt; b++)
        if (fp->compute_array(a, b) != fp->compute_array(0, 0))
          return std::string("fix property/global ") + name +
                 " differs between atom type pairs; the paper's law has one value";
    return "";
  }
};

// LIGGGHTS 3.8 cannot end a run early: nothing to do
inline void end_run(LAMMPS *) {}

}    // namespace servo_bc_host
}    // namespace LAMMPS_NS

#endif
