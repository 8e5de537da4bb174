/* -*- c++ -*- ----------------------------------------------------------
   fix servo_bc/bonds: bonded particles computed by the servo_bc core, between
   the group's particles that touch at set-up:
   - beam | parallel: the thesis' 3D bonded particle model (Timoshenko beams
     or parallel bonds; bpm_host.h, the kernels of the embedded 3D engine);
   - cohesive: the paper's 2D cohesive bonds (eqs. 7-8) and, once broken or
     between discs that were apart, its frictional contacts (eq. 6): every
     contact of the group (cohesive_host.h, the embedded 2D engine's pair
     loop); the pair style must leave the group alone (pair_style zero or
     none), and fix servo_bc takes its contact sums from this fix.
   Every rank gathers the group's centres and velocities in atom-ID order
   each step and runs the same loop, so the loads do not depend on the rank
   count; each rank adds them to the atoms it owns.
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

#include "sbc/bpm_host.h"
#include "sbc/cohesive_host.h"
#include "sbc/contact.h"
#include "sbc/saved.h"

namespace LAMMPS_NS {

class FixServoBCBonds : public Fix {
 public:
  FixServoBCBonds(class LAMMPS *, int, char **);
  ~FixServoBCBonds() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void post_force(int) override;
  void post_run() override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // cohesive: every contact of the group is this fix's (fix servo_bc asks)
  bool owns_contacts() const { return model == "cohesive"; }
  double contact_kn() const { return kn; }    // N/m
  void contact_sums(double out[4]) const;    // relax.h's sums of the last step, the same on every rank

 private:
  std::string model;
  double E, nu, alpha;                     // beam, parallel
  double strength[5];                      // optional failure: FT FS MB MT (N, N, N m, N m), friction MU
  bool failure;                            // a strength was given
  double fracture_saved = 0.0;             // the broken bonds' energy from a restart file, J
  std::string words;                       // cohesive: the law's words (cohesive_host.h)
  double kn;                               // cohesive: the law's kn, N/m
  sbc_cohesive law;                        // cohesive: the law (eqs. 6-8), saved in restart files
  sbc_bpm *bonds;
  sbc_cohesive_host *contacts;
  int n;                                   // particles of the group
  int dim;                                 // 3 (beam, parallel) or 2 (cohesive): components gathered per vector
  std::vector<tagint> tags;                // atom IDs in order (the core's sphere order)
  std::vector<double> ref_x, ref_r, ref_m; // the spheres at bond creation (restart rebuilds from them)
  std::vector<double> saved;               // bond states from a restart file, set in init()
  std::vector<tagint> saved_tags;          // cohesive: the atom IDs of the restart file's pair state
  std::unordered_map<tagint, int> index;   // atom ID -> sphere
  std::vector<double> mine, all, load;     // gather buffers: x | v | omega; loads (6 per sphere in 3D, 3 per disc in 2D)
  bigint last_step;                        // the step whose loads are in `load`
  int reported;                            // cohesive: the intact bonds post_run last printed
  // eqs. 49-53 (beam, parallel): the loads on the group other than the bonds' at the last
  // end of step (6 per sphere, tag order), and the energies (J)
  std::vector<double> other, other_prev, other_mine;
  double kinetic, external_work;
  bool have_prev;
  void energy_step();
  std::string last_error;
  void create_bonds();
  void bond_spheres();
  void bond_discs();
  void gather();
  void fail(const std::string &message);
  void say(const char *line);
  double number(const char *keyword, const char *word);
};

}    // namespace LAMMPS_NS

#endif
#endif
