/* -*- c++ -*- ----------------------------------------------------------
   fix servo_bc/bonds: the thesis' 3D bonded particle model (Timoshenko beams
   or parallel bonds) between the group's spheres that touch at set-up,
   computed by the servo_bc core (bpm_host.h, the kernels of the embedded 3D
   engine). Every rank gathers the group's centres and velocities in atom-ID
   order each step and runs the same bond loop, so the loads do not depend
   on the rank count; each rank adds them to the atoms it owns.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
FixStyle(servo_bc/bonds,FixServoBCBonds);
#else

#ifndef LMP_FIX_SERVO_BC_BONDS_H
#define LMP_FIX_SERVO_BC_BONDS_H

#include "fix.h"

#include <string>
#include <unordered_map>
#include <vector>

extern "C" {
#include "sbc/bpm_host.h"
}

namespace LAMMPS_NS {

class FixServoBCBonds : public Fix {
 public:
  FixServoBCBonds(class LAMMPS *, int, char **);
  ~FixServoBCBonds() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

 private:
  std::string model;
  double E, nu, alpha;
  sbc_bpm *bonds;
  int n;                                   // spheres of the group
  std::vector<tagint> tags;                // atom IDs in order (the core's sphere order)
  std::vector<double> ref_x, ref_r, ref_m; // the spheres at bond creation (restart rebuilds from them)
  std::vector<double> saved;               // bond states from a restart file, set in init()
  std::unordered_map<tagint, int> index;   // atom ID -> sphere
  std::vector<double> mine, all, load;     // gather buffers: x | v | omega (3n each); loads (6 per sphere)
  bigint last_step;                        // the step whose loads are in `load`
  std::string last_error;
  void create_bonds();
  void bond_spheres();
  void gather();
  void fail(const std::string &message);
};

}    // namespace LAMMPS_NS

#endif
#endif
