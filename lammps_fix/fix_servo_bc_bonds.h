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
   Every model keeps each pair's state with its atoms: both atoms of a bond
   (cohesive: of a bond or a contact with a tangential spring) hold a copy of
   its state in per-atom slots that migrate between ranks and go into restart
   files; each rank computes the pairs of the atoms it owns, the partner a
   ghost when another rank owns it (its velocity and spin by this fix's
   forward communication), with the smaller atom ID as end A, so both owners
   advance their copies alike and agree when a bond breaks. Beam and parallel
   (fix_servo_bc_bonds_slots.cpp) keep the bonds formed at the first run;
   cohesive (fix_servo_bc_bonds_contacts.cpp) also finds the group's new
   contacts at each neighbour build, within the neighbour skin.
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
  void pre_exchange() override;
  void end_of_step() override;
  double compute_scalar() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  // beam | parallel: per-atom slots (fix_servo_bc_bonds_slots.cpp)
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
#ifdef SERVO_BC_LIGGGHTS
  int pack_comm(int, int *, double *, int, int *) override;
  void unpack_comm(int, int, double *) override;
#else
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
#endif

  // cohesive: every contact of the group is this fix's (fix servo_bc asks)
  bool owns_contacts() const { return dim == 2; }
  double contact_kn() const { return kn; }    // N/m
  void contact_sums(double out[4]) const;    // relax.h's sums of the last step over this rank's pairs (end A owned)

 private:
  std::string model;
  double E, nu, alpha;                     // beam, parallel
  double strength[5];                      // optional failure: FT FS MB MT (N, N, N m, N m), friction MU
  bool failure;                            // a strength was given
  double kn;                               // cohesive: the law's kn, N/m
  sbc_cohesive law;                        // cohesive: the law (eqs. 6-8), saved in restart files
  sbc_bpm *bonds;                          // beam | parallel: the law (no spheres; bpm_host.h)
  int n;                                   // particles of the group
  int dim;                                 // 3 (beam, parallel) or 2 (cohesive)
  int reported;                            // the intact bonds post_run last printed
  // cohesive: the pairs of the owned atoms since the last neighbour build
  // (fix_servo_bc_bonds_contacts.cpp), each once on this rank: its ends as
  // owned or ghost indices, end A (the smaller ID) first; the pairs whose end
  // A is owned come first (relax.h's sums count them, each pair on one rank)
  std::vector<int> pair_ends;              // 2 per pair
  std::vector<double> pair_state;          // SBC_COHESIVE_PAIR_STATE per pair
  long pairs_counted;                      // pairs with end A owned
  std::vector<double> contact_load;        // this step's loads of each pair: on end A (3), on end B (3)
  std::vector<int> load_start, load_at;    // per owned atom, its pairs' loads in contact_load in partner ID order
  bool have_contacts;                      // the bonds formed (first run or restart file)
  double contact_mine[4];                  // relax.h's sums of the last step over the pairs whose end A is owned
  int intact_mine;                         // intact bonds whose end A is owned
  // beam | parallel: per atom, slot[i] = count, then per bond the partner's
  // ID and the bond's state (per doubles); carry[i] = the other loads of the
  // last end of step (6), the external work of eq. 52 on this atom (J) and
  // the fracture energy of the bonds it is end A of (J); both migrate
  double rmin;                             // the smallest radius of the group at creation, m
  int maxb, per, width;                    // slots per atom, doubles per bond state, doubles per atom
  double critical_dt;                      // eq. 48 at creation, s
  int formed;                              // bonds formed (every rank)
  double **slot, **carry;
  double **step_load, **step_motion;       // this step's bond loads (6) and motion v | omega (6), local atoms
  int **partner_at;                        // per slot of an owned atom: its partner's owned or ghost index (-1:
                                           // a broken bond's partner out of reach)
  int **partner_slot;                      // the partner's slot of the same bond when it is owned here, else -1
  double **slot_load;                      // this step's load of each slot's bond on the atom (6 per slot)
  std::vector<int> slot_count;             // the owned atoms' bonds at the last neighbour build
  int nmax_slots;                          // rows allocated
  bool have_prev;                          // carry holds a last end of step's loads
  bool restarted;                          // slots came from a restart file
  bool copies_stale;                       // end B's copies lag end A's (sync_copies)
  double longest;                          // the longest bond at creation, m
  std::unordered_map<tagint, int> image_first;  // atom ID -> a local or ghost index; image_next chains
  std::vector<int> image_next;                  // the other indices of the same ID (periodic images), -1 ends
  bigint reduced_at;                       // the step the outputs below were summed over ranks
  double sums[5];                          // strain, intact bonds, kinetic, dissipated, external work
  double kinetic_mine;                     // eq. 49 on this rank's atoms at the last end of step
  std::string breaks_file;                 // keyword breaks: a row per broken bond
  FILE *breaks_fp;
  std::vector<double> break_rows;          // this step's breaks on this rank: step, ID A, ID B, x, y, z
  void survey_group(double &rmax, double &mmin);
  void create_slots();
  void size_slots();
  void map_images();
  void map_partners();
  int partner(tagint tag, const double *near) const;
  void step_slots(bool motion);
  void sync_copies();
  void energy_slots();
  void write_breaks();
  void reduce_outputs();
  std::string last_error;
  double ghost_cutoff() const;
  void create_contacts();
  void build_contacts(bool fresh);
  void step_contacts(bool motion);
  void sync_contacts();
  void fail(const std::string &message);
  void fail_here(const std::string &message);
  void say(const char *line);
  double number(const char *keyword, const char *word);
};

}    // namespace LAMMPS_NS

#endif
#endif
