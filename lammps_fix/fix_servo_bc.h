/* -*- c++ -*- ----------------------------------------------------------
   fix servo_bc: micro-scale boundary conditions (D), (P), (T) on a frame of
   boundary particles, driven by the servo_bc core (pure C, src_core/).
   The fix only translates: owned frame atoms -> snapshot, MPI sums, core
   controller step, commands -> owned frame atoms.
   One source for LAMMPS and LIGGGHTS (-DSERVO_BC_LIGGGHTS): where their Fix
   APIs differ, the host header below says how.
------------------------------------------------------------------------- */

#ifdef FIX_CLASS
// clang-format off
FixStyle(servo_bc,FixServoBC);
// clang-format on
#else

#ifndef LMP_FIX_SERVO_BC_H
#define LMP_FIX_SERVO_BC_H

#include "fix.h"

#ifdef SERVO_BC_LIGGGHTS
#include "fix_servo_bc_liggghts.h"
#else
#include "fix_servo_bc_lammps.h"
#endif

#include <string>
#include <unordered_map>
#include <vector>

#include "sbc/confine.h"
#include "sbc/controller.h"
#include "sbc/driver.h"
#include "sbc/fire_damping.h"
#include "sbc/frame.h"
#include "sbc/results.h"
#include "sbc/saved.h"
#include "sbc/seal.h"
#include "sbc/time_step.h"
#include "sbc/settings.h"
#include "sbc/version.h"

namespace LAMMPS_NS {

class FixServoBCBonds;

class FixServoBC : public Fix {
 public:
  FixServoBC(class LAMMPS *, int, char **);
  ~FixServoBC() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void post_force(int) override;
  void post_run() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;

  // per-atom rotation angle: LAMMPS keeps none for spheres (eq. 41 needs it)
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;

 private:
  sbc_settings settings;
  sbc_frame frame;
  sbc_controller *ctl;
  sbc_driver *driver;              // the per-step protocol (driver.h), over this fix's callbacks
  std::vector<tagint> frame_tag;   // [Q] atom IDs in frame order
  std::vector<double> frame_mass;  // [Q] kg
  std::unordered_map<tagint, int> slot;  // atom ID -> frame position, built with the frame
  double **per_atom;               // per atom: frame flag (1 frame, 0 other), accumulated rotation (rad)
  double **stream;                 // per atom: the velocity of keyword remap x to be taken back (m/s)
  int stream_rows;                 // rows of stream zeroed so far
  int streaming;                   // some atom of this rank carries a remap velocity
  int interior_bit, frame_bit;     // groups ID_interior, ID_frame created by the fix
  int dim = 2;                       // the box's dimension (domain->dimension)
  int nrot = 1;                      // SBC_ROTATIONS(dim): rotation components (z alone in 2d)
  int zrot = 2;                      // the first of them in omega and torque (0 in 3d)
  servo_bc_host::ContactLaw law;   // kn, kt, shear history of the pair style
  FixServoBCBonds *contacts;       // fix servo_bc/bonds cohesive, which owns the contacts instead (or null)
  sbc_csv csv;
  int finished;
  sbc_result last;
  std::vector<double> saved_state;  // controller state from a restart file, loaded in init()
  int restored;                      // the frame came from a restart file
  bigint last_step;                  // timestep of the last controller step
  bigint run_start;                  // timestep at the setup of this run
  double clock_start, clock_reported; // MPI_Wtime at the first setup and at the last progress line or row, s
  int frame_still;                   // steps since the commands last changed (initial_integrate)
  int any_free;                      // some frame rotation is free ((T)): integrated every step
  sbc_fire_state fire;               // damping fire: FIRE's state as a restart file gave it (the driver's after init)
  sbc_seal seal;                     // keyword seal: walls on the frame's polygon (seal.h)
  int seal_on;                       // seal initialised
  std::vector<double> seal_reaction; // [3Q] the walls' reactions on the frame from this rank's atoms, N
  double seal_energy;                // the walls' energy from this rank's atoms, J
  int slow_step_noted = 0;           // the time step's note (time_step.h) given, once per fix

  void find_contacts();
  void seal_pass();
  void progress();
  static int seal_slot(const void *self, int i);
  // this rank's share of each measure the driver asks for (driver.h)
  void fire_pass(double *sums);
  template <int DIM> void fire_loop(double *sums);
  void remap_pass(const double *M, const double *origin, int sign);
  void interior_pass(bool again, const sbc_fire_mix *mix, double out[2]);
  template <int DIM, bool LOCAL> void interior_loop(bool again, const sbc_fire_mix *mix, double out[2]);
  void contact_pass(double out[4]);
  void frame_pass(double *buf);
  int confined(const double *fx, int increment, char *message, size_t cap);
  void write_row(const char *line);
  void make_driver();
  void detect_frame();
  void make_buffers();
  void fail(const std::string &message);
  void fail_here(const std::string &message);
  std::string last_error;
  void log(const char *format, ...) __attribute__((format(printf, 2, 3)));
};

}    // namespace LAMMPS_NS

#endif
#endif
