/* What fix servo_bc (fix_servo_bc.cpp, one source for LAMMPS and LIGGGHTS)
   takes from LAMMPS where LIGGGHTS differs; the LIGGGHTS side is
   liggghts_fix/fix_servo_bc_liggghts.h. Three differences, named:
   - contact law: where kn, kt and the per-contact shear history live;
   - inertia: the moment of inertia the integrator gives a particle;
   - end of run: how the fix ends a run when the loading path is done. */
#ifndef SERVO_BC_HOST_LAMMPS_H
#define SERVO_BC_HOST_LAMMPS_H

#include "fix_neigh_history.h"
#include "force.h"
#include "lammps.h"
#include "pair_gran_hooke_history.h"
#include "timer.h"

#include <string>

namespace LAMMPS_NS {
namespace servo_bc_host {

// I = inertia m r^2: fix nve/sphere disc gives 2d discs the paper's 1/2 (eq. 9)
constexpr double inertia = 0.5;
// the integrator's words for that (error messages)
constexpr const char *disc_keyword = " disc";
// Error::one writes its message to the log file too
constexpr bool one_writes_log = true;
constexpr const char *contact_law = "pair_style gran/hooke/history KN KT 0 0 MU 0";

// kn, kt and fix_history are protected in PairGranHookeHistory; a derived
// class may name them (a pointer to member taken in its scope)
struct GranAccess : PairGranHookeHistory {
  static double kn_of(PairGranHookeHistory *p) { return p->*(&GranAccess::kn); }
  static double kt_of(PairGranHookeHistory *p) { return p->*(&GranAccess::kt); }
  static FixNeighHistory *history_of(PairGranHookeHistory *p) { return p->*(&GranAccess::fix_history); }
  static double gamman_of(PairGranHookeHistory *p) { return p->*(&GranAccess::gamman); }
  static double gammat_of(PairGranHookeHistory *p) { return p->*(&GranAccess::gammat); }
  static int dampflag_of(PairGranHookeHistory *p) { return p->*(&GranAccess::dampflag); }
};

/* eq. 6 as pair gran/hooke/history holds it: kn, kt (N/m) and, per neighbour
   jj of atom i, the elastic shear displacement at history(i)[stride*jj + offset] */
struct ContactLaw {
  double kn = 0.0, kt = 0.0;
  int stride = 3, offset = 0;
  PairGranHookeHistory *pair = nullptr;

  // "" when found, else what is missing
  std::string attach(LAMMPS *lmp)
  {
    pair = dynamic_cast<PairGranHookeHistory *>(lmp->force->pair_match("gran/hooke/history", 1));
    if (!pair) return std::string("requires ") + contact_law + " (the paper's contact law, eq. 6)";
    kn = GranAccess::kn_of(pair);
    kt = GranAccess::kt_of(pair);
    // eq. 6 has no dashpots: the damping of the relaxation is the fix's
    const double gn = GranAccess::gamman_of(pair), gt = GranAccess::gammat_of(pair);
    const int flag = GranAccess::dampflag_of(pair);
    if (gn != 0.0 || gt != 0.0 || flag != 0)
      return std::string("requires ") + contact_law + " (the paper's contact law, eq. 6, has no dashpots); this " +
             "script gives gamman " + std::to_string(gn) + ", gammat " + std::to_string(gt) + ", dampflag " +
             std::to_string(flag) + " (set them to 0 0 and 0)";
    return "";
  }
  NeighList *list() const { return pair->list; }
  double **history() const
  {
    FixNeighHistory *h = GranAccess::history_of(pair);
    return h ? h->firstvalue : nullptr;
  }
};

// ends this run at the next step
inline void end_run(LAMMPS *lmp)
{
  lmp->timer->force_timeout();
}

}    // namespace servo_bc_host
}    // namespace LAMMPS_NS

#endif
