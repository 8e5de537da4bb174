/* ----------------------------------------------------------------------
   fix servo_bc for LAMMPS and LIGGGHTS (see fix_servo_bc.h). Same keywords as
   every host: the words after the style are parsed by the core
   (sbc_settings_parse). Only the Fix API the two hosts share is used here;
   the rest is in fix_servo_bc_lammps.h / fix_servo_bc_liggghts.h.
------------------------------------------------------------------------- */

#include "fix_servo_bc.h"
#include "fix_servo_bc_bonds.h"
#include "sbc/damping.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <csignal>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <unordered_map>

#include "sbc/columns.h"
#include "sbc/results.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {
enum { CALLBACK_GROW = 0, CALLBACK_RESTART = 1 };    // Atom::GROW, Atom::RESTART in LAMMPS
}    // namespace

FixServoBC::FixServoBC(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), ctl(nullptr), driver(nullptr), per_atom(nullptr), stream(nullptr), stream_rows(0), streaming(0), contacts(nullptr), finished(0), restored(0), last_step(-1), run_start(0), clock_start(-1.0), clock_reported(-1.0), frame_still(0), any_free(1), seal_on(0), seal_energy(0.0)
{
  sbc_error err;
  std::memset(&frame, 0, sizeof frame);
  std::memset(&last, 0, sizeof last);
  std::memset(&seal, 0, sizeof seal);
  std::memset(&csv, 0, sizeof csv);
  sbc_fire_start(&fire);
  if (sbc_settings_parse(&settings, narg - 3, arg + 3, &err) != SBC_OK ||
      sbc_settings_check_dimension(&settings, domain->dimension, &err) != SBC_OK ||
      sbc_settings_check_host(&settings, &err) != SBC_OK)
    fail(err.message);
  if (!atom->sphere_flag) fail("requires atom_style sphere");
  if (std::strcmp(update->unit_style, "si") != 0)
    fail(std::string("requires units si (its outputs are in m, N/m and s; this script has units ") +
         update->unit_style + ")");
  dim = domain->dimension;
  nrot = SBC_ROTATIONS(dim);
  zrot = 3 - nrot;
  if (dim == 3 && settings.frame_group[0]) fail("keyword 'frame' is 2d in this version; the box is 3d");
  {
    char note[SBC_ERROR_LEN];
    if (comm->me == 0 && sbc_settings_ignored_message(&settings, note, sizeof note))
      error->warning(FLERR, (std::string("Fix servo_bc: ") + note).c_str());
  }

  vector_flag = 1;
  size_vector = SBC_THERMO_COUNT;
  global_freq = 1;
  extvector = 0;
  time_integrate = 0;    // moves only the frame atoms, which no integrator may own (checked in init)
  restart_global = 1;
  restart_peratom = 1;

  // per-atom outputs for dumps (f_ID[1] frame flag, f_ID[2] accumulated rotation about z, rad;
  // in 3d f_ID[2..4] the accumulated rotation vector)
  peratom_flag = 1;
  size_peratom_cols = 1 + nrot;
  peratom_freq = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(CALLBACK_GROW);
  atom->add_callback(CALLBACK_RESTART);
  for (int i = 0; i < atom->nlocal; i++)
    for (int c = 0; c <= nrot; c++) per_atom[i][c] = 0.0;
  // a results file past the file size limit is a write error with a message,
  // not a process killed by SIGXFSZ without one
  if (settings.file[0]) std::signal(SIGXFSZ, SIG_IGN);

  // after read_restart, the groups ID_frame and ID_interior come back with the
  // atoms; the frame then comes from this fix's restart data (restart()), since
  // its reference positions cannot be detected again from a deformed packing
  int igf = group->find((std::string(id) + "_frame").c_str());
  int igi = group->find((std::string(id) + "_interior").c_str());
  if (igf >= 0 && igi >= 0) {
    frame_bit = group->bitmask[igf];
    interior_bit = group->bitmask[igi];
  } else {
    detect_frame();
  }
}

FixServoBC::~FixServoBC()
{
  atom->delete_callback(id, CALLBACK_GROW);
  atom->delete_callback(id, CALLBACK_RESTART);
  memory->destroy(per_atom);
  memory->destroy(stream);
  sbc_driver_free(driver);
  sbc_controller_free(ctl);
  sbc_seal_free(&seal);
  sbc_frame_free(&frame);
  sbc_csv_close(&csv);
}

int FixServoBC::setmask()
{
  return INITIAL_INTEGRATE | POST_FORCE;
}

/* gather the group's atoms on every rank, in tag order (rank-independent),
   let the core find the frame, and create groups ID_frame and ID_interior */
void FixServoBC::detect_frame()
{
  const int nlocal = atom->nlocal, *mask = atom->mask;
  int frame_group_bit = 0;
  if (settings.frame_group[0]) {
    int ig = group->find(settings.frame_group);
    if (ig < 0)
      fail(std::string("keyword 'frame': group '") + settings.frame_group + "' does not exist");
    frame_group_bit = group->bitmask[ig];
  }
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit)
      mine.insert(mine.end(), {(double) atom->tag[i], atom->x[i][0], atom->x[i][1], atom->x[i][2], atom->radius[i],
                               atom->rmass[i], (mask[i] & frame_group_bit) ? 1.0 : 0.0});
  int nmine = (int) mine.size(), nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  int ntot = displs[nprocs - 1] + counts[nprocs - 1];
  std::vector<double> all(ntot);
  MPI_Allgatherv(mine.data(), nmine, MPI_DOUBLE, all.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  const int per = 7;    // tag, x, y, z, radius, mass, listed
  int n = ntot / per;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return all[per * a] < all[per * b]; });
  std::vector<double> x(dim * n), r(n), m(n);
  std::vector<int> listed;
  for (int k = 0; k < n; k++) {
    const double *a = &all[per * order[k]];
    for (int c = 0; c < dim; c++) x[dim * k + c] = a[1 + c];
    r[k] = a[4];
    m[k] = a[5];
    if (a[6] != 0.0) listed.push_back(k);
  }
  sbc_error err;
  sbc_status st = dim == 3 ? sbc_frame_detect_3d(&frame, n, x.data(), r.data(), 0.0, &err)
      : settings.frame_group[0]
      ? sbc_frame_from_list(&frame, (int) listed.size(), listed.data(), x.data(), r.data(), &err)
      : sbc_frame_detect(&frame, n, x.data(), r.data(), 0.0, &err);
  if (st != SBC_OK) fail(err.message);

  const int Q = frame.n;
  frame_tag.resize(Q);
  frame_mass.resize(Q);
  std::unordered_map<tagint, int> is_frame;
  for (int q = 0; q < Q; q++) {
    frame_tag[q] = (tagint) all[per * order[frame.particle[q]]];
    frame_mass[q] = m[frame.particle[q]];
    is_frame[frame_tag[q]] = q;
  }
  std::vector<int> in_frame(nlocal), in_interior(nlocal);
  for (int i = 0; i < nlocal; i++) {
    in_frame[i] = (mask[i] & groupbit) && is_frame.count(atom->tag[i]);
    in_interior[i] = (mask[i] & groupbit) && !in_frame[i];
  }
  const std::string gf = std::string(id) + "_frame", gi = std::string(id) + "_interior";
  group->create(gf.c_str(), in_frame.data());
  group->create(gi.c_str(), in_interior.data());
  frame_bit = group->bitmask[group->find(gf.c_str())];
  interior_bit = group->bitmask[group->find(gi.c_str())];
  make_buffers();
  log("fix servo_bc (servo_bc %s): %d particles, frame of %d (groups %s, %s)\n", sbc_version(), n, Q, gf.c_str(),
      gi.c_str());
}

void FixServoBC::make_buffers()
{
  slot.clear();
  for (int q = 0; q < frame.n; q++) slot[frame_tag[q]] = q;
}

/* a fix servo_bc/bonds cohesive on this fix's atoms owns their contacts
   (eqs. 6-8 in the core): the contact sums and kn come from it, and its
   loads must be on the atoms before this fix measures them */
void FixServoBC::find_contacts()
{
  contacts = nullptr;
  int me = -1, other = -1;
  for (int k = 0; k < modify->nfix; k++) {
    if (modify->fix[k] == this) me = k;
    auto *b = dynamic_cast<FixServoBCBonds *>(modify->fix[k]);
    if (b && b->owns_contacts()) {
      if (contacts) fail("more than one fix servo_bc/bonds cohesive (one owns the contacts)");
      contacts = b;
      other = k;
    }
  }
  if (!contacts) return;
  if (other > me)
    fail(std::string("fix servo_bc/bonds ") + contacts->id + " must come before fix servo_bc " + id +
         " in the input (its contact loads are part of what this fix measures)");
  if (contacts->igroup != igroup && contacts->igroup != 0)    // 0: group all
    fail(std::string("fix servo_bc/bonds ") + contacts->id + " must act on this fix's group or on all");
  law.kn = contacts->contact_kn();
}

void FixServoBC::init()
{
  if (frame.n == 0)
    fail(std::string("groups ") + id + "_frame and " + id + "_interior exist but no restart data of fix " + id +
         " restored the frame (re-use the fix ID of the restart file, or delete the groups)");
  find_contacts();
  if (!contacts) {
    std::string missing = law.attach(lmp);
    if (!missing.empty()) fail(missing);
  }
  {    // the time step against the lightest atom's critical step (sbc/time_step.h)
    struct {
      double mass;
      int rank;
    } mine = {1e300, comm->me}, lightest;
    tagint id_local = 0, id_lightest = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & groupbit) && atom->rmass[i] < mine.mass) {
        mine.mass = atom->rmass[i];
        id_local = atom->tag[i];
      }
    MPI_Allreduce(&mine, &lightest, 1, MPI_DOUBLE_INT, MPI_MINLOC, world);
    id_lightest = id_local;
    MPI_Bcast(&id_lightest, 1, MPI_LMP_TAGINT, lightest.rank, world);
    sbc_error err;
    if (lightest.mass < 1e300 &&
        sbc_time_step_check(update->dt, law.kn, lightest.mass, (long) id_lightest, settings.max_relax_steps, &err) !=
            SBC_OK)
      fail(std::string(err.message) + (strstr(err.message, "particle")
                                            ? " (particle = atom ID; discs need a disc's mass: 'set mass', not 'set density')"
                                            : ""));
    char note[SBC_ERROR_LEN];
    if (comm->me == 0 && !slow_step_noted && lightest.mass < 1e300 &&
        sbc_time_step_note_mass(&settings, update->dt, law.kn, lightest.mass, note, sizeof note))
      error->warning(FLERR, (std::string("Fix servo_bc: ") + (strncmp(note, "servo_bc: ", 10) ? note : note + 10)).c_str());
    slow_step_noted = 1;
  }
  {    // every interior atom is integrated by some fix (else the servo waits for ever), and so is every atom
       // outside the fix's group (else the specimen is larger than the group, and its rows are not the specimen's)
    int orphans[2] = {0, 0}, all[2] = {0, 0};
    for (int i = 0; i < atom->nlocal; i++) {
      const int inside = atom->mask[i] & groupbit;
      if (inside && !(atom->mask[i] & interior_bit)) continue;
      int owned = 0;
      for (int k = 0; k < modify->nfix && !owned; k++)
        owned = modify->fix[k] != this && (modify->fmask[k] & INITIAL_INTEGRATE) &&
                (atom->mask[i] & modify->fix[k]->groupbit);
      orphans[inside ? 0 : 1] += !owned;
    }
    MPI_Allreduce(orphans, all, 2, MPI_INT, MPI_SUM, world);
    if (all[1])
      fail(std::to_string(all[1]) + " atoms outside group " + group->names[igroup] +
           " are integrated by no fix: the fix's group holds the whole specimen, whose boundary it finds (use group "
           "all; keyword frame names a group of boundary particles in 2d)");
    if (all[0])
      fail(std::to_string(all[0]) + " atoms of group " + id + "_interior are integrated by no fix (add: fix integrate " +
           id + "_interior nve/sphere" + servo_bc_host::disc_keyword + ")");
  }
  if (restored) {    // the saved atom IDs must be the frame group's, each once
    int local[2] = {0, 0}, all[2];
    for (int i = 0; i < atom->nlocal; i++)
      if (atom->mask[i] & frame_bit) {
        local[0]++;
        if (!slot.count(atom->tag[i])) local[1]++;
      }
    MPI_Allreduce(local, all, 2, MPI_INT, MPI_SUM, world);
    if (all[1] || all[0] != frame.n || (int) slot.size() != frame.n)
      fail(std::string("restart: the saved frame of ") + std::to_string(frame.n) + " atoms (" +
           std::to_string(slot.size()) + " distinct IDs) is not group " + id + "_frame (" + std::to_string(all[0]) +
           " atoms, " + std::to_string(all[1]) + " not in the saved frame)");
  }

  // frame atoms are moved by this fix only
  for (int k = 0; k < modify->nfix; k++) {
    Fix *other = modify->fix[k];
    if (other == this || !(modify->fmask[k] & INITIAL_INTEGRATE)) continue;
    int mine = 0, any = 0;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & frame_bit) && (atom->mask[i] & other->groupbit)) mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
    if (any)
      fail(std::string("frame atoms are also integrated by fix ") + other->id + " (" + other->style +
           "); integrate group " + id + "_interior instead");
  }


  if (settings.seal && !seal_on) {    // the Verlet margin: a quarter of the smallest frame radius
    sbc_error err;
    if (sbc_seal_init(&seal, &frame, 0.25 * *std::min_element(frame.R, frame.R + frame.n), &err) != SBC_OK)
      fail(err.message);
    seal_on = 1;
    seal_reaction.assign(3 * frame.n, 0.0);
  }
  if (!ctl) {
    sbc_error err;
    ctl = sbc_controller_create(&frame, &settings, frame_mass.data(), update->dt, law.kn, &err);
    if (!ctl) fail(err.message);
    if (!saved_state.empty() && sbc_controller_load(ctl, saved_state.data(), saved_state.size(), &err) != SBC_OK)
      fail(err.message);
    make_driver();
    // continued from a restart: the rows an interrupted run wrote after the
    // restart file are dropped, so that the file equals an uninterrupted run's
    int kept = 0;
    if (comm->me == 0 && settings.file[0] &&
        (restored ? sbc_csv_resume(&csv, settings.file, settings.dim, finished ? INT_MAX : sbc_controller_increment(ctl), &kept, &err)
                  : sbc_csv_open(&csv, settings.file, settings.dim, &err)) != SBC_OK)
      fail_here(err.message);
    if (restored && settings.file[0])
      log("servo_bc: %s continued after its row of increment %d (%d rows kept)\n", settings.file,
          finished ? sbc_settings_total_increments(&settings) : sbc_controller_increment(ctl) - 1, kept);
  }
}

void FixServoBC::setup(int)
{
  run_start = update->ntimestep;
  if (clock_start < 0.0) clock_start = clock_reported = MPI_Wtime();
  for (int i = 0; i < atom->nlocal; i++) per_atom[i][0] = (atom->mask[i] & frame_bit) ? 1.0 : 0.0;
  post_force(0);
}

/* a run that ends before the loading path does says so (LAMMPS; LIGGGHTS runs
   in pieces until f_ID[18] is 1, and its last piece ends the path) */
void FixServoBC::post_run()
{
#ifndef SERVO_BC_LIGGGHTS
  if (!finished && update->ntimestep > run_start && comm->me == 0)
  {
    char text[256];
    std::snprintf(text, sizeof text,
                  "Fix servo_bc: the run ended at increment %d of %d: the loading path is unfinished (run more "
                  "steps; f_%s[18] is 1 when it is done)",
                  sbc_controller_increment(ctl), sbc_settings_total_increments(&settings), id);
    error->warning(FLERR, text);
  }
#endif
}

/* move the owned frame atoms to the commanded targets within this step */
void FixServoBC::initial_integrate(int)
{
  if (finished) return;
  // a frame at rest on unchanged targets with no free rotation stays as it is
  // (x = target, v = omega = 0 since the step after the last move)
  if (frame_still >= 2 && !any_free) return;
  frame_still++;
  const double dt = update->dt;
  sbc_commands cmd = sbc_controller_commands(ctl);
  any_free = 0;
  for (int q = 0; q < frame.n; q++) any_free |= cmd.free_rotation[q];
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & frame_bit)) continue;
    int q = slot[atom->tag[i]];
    for (int c = 0; c < 3; c++) {    // 2d: the third slot is 0
      v[i][c] = c < dim ? (cmd.x[3 * q + c] - x[i][c]) / dt : 0.0;
      if (c < dim) x[i][c] = cmd.x[3 * q + c];
    }
    const double I = (dim == 3 ? 0.4 : servo_bc_host::inertia) * atom->rmass[i] * atom->radius[i] * atom->radius[i];
    for (int c = 0; c < nrot; c++) {
      double &w = omega[i][zrot + c], &turned = per_atom[i][1 + c];
      if (cmd.free_rotation[q]) {    // (T): free rotation with the damping of eq. 10
        const double t = torque[i][zrot + c], m = settings.damping ? sbc_damp_local(t, w, settings.beta) : t;
        w = w + dt * m / I;
        turned += dt * w;
      } else {
        w = (cmd.theta[nrot * q + c] - turned) / dt;
        turned = cmd.theta[nrot * q + c];
      }
    }
  }
}

/* seal.h: the walls of the frame's polygon or surface (at the commanded frame centres,
   where initial_integrate put the frame atoms) on this rank's atoms; their
   reactions on the frame wait in seal_reaction for frame_pass's sum */
int FixServoBC::seal_slot(const void *self, int i)
{
  const FixServoBC *me = static_cast<const FixServoBC *>(self);
  const int mask = me->atom->mask[i];
  if (mask & me->frame_bit) return me->slot.at(me->atom->tag[i]);
  return (mask & me->interior_bit) ? -1 : -2;
}

void FixServoBC::seal_pass()
{
  std::fill(seal_reaction.begin(), seal_reaction.end(), 0.0);
  seal_energy = 0.0;
  if (!seal_on || atom->nlocal == 0) return;
  sbc_commands cmd = sbc_controller_commands(ctl);
  sbc_seal_particles p = {atom->nlocal, &atom->x[0][0], &atom->f[0][0], 3, atom->radius, seal_slot, this};
  sbc_error err;
  // local indices change when LAMMPS re-neighbours: collect the candidates again
  if (sbc_seal_forces(&seal, &frame, cmd.x, &p, law.kn, neighbor->ago == 0, seal_reaction.data(), &seal_energy,
                      &err) != SBC_OK)
    fail(err.message);
}

/* the driver (driver.h) over this fix's passes; FIRE's state from a restart file */
void FixServoBC::make_driver()
{
  sbc_driver_callbacks cb = {};
  cb.user_data = this;
  cb.fire_sums = [](void *self, double *sums) { static_cast<FixServoBC *>(self)->fire_pass(sums); };
  cb.interior = [](void *self, const sbc_fire_mix *mix, int again, double out[2]) {
    static_cast<FixServoBC *>(self)->interior_pass(again != 0, mix, out);
  };
  cb.contacts = [](void *self, double out[4]) { static_cast<FixServoBC *>(self)->contact_pass(out); };
  cb.frame = [](void *self, double *buf) { static_cast<FixServoBC *>(self)->frame_pass(buf); };
  cb.reduce = [](void *self, const double *in, double *out, int n, sbc_reduce_op op) {
    MPI_Allreduce(in, out, n, MPI_DOUBLE, op == SBC_REDUCE_MAX ? MPI_MAX : MPI_SUM, static_cast<FixServoBC *>(self)->world);
  };
  cb.confined = [](void *self, const double *fx, int increment, char *message, size_t cap) {
    return static_cast<FixServoBC *>(self)->confined(fx, increment, message, cap);
  };
  cb.row = [](void *self, const sbc_result *, const char *line, char *, size_t) {
    static_cast<FixServoBC *>(self)->write_row(line);
    return 0;
  };
  cb.remap = [](void *self, const double *M, const double *origin, int sign) {
    static_cast<FixServoBC *>(self)->remap_pass(M, origin, sign);
  };
  sbc_error err;
  if (!(driver = sbc_driver_create(ctl, &settings, &cb, &err))) fail(err.message);
  *sbc_driver_fire(driver) = fire;
}

/* keyword remap x (driver.h): the interior's velocity gains the frame's
   affine move over one step, which the integrator's next x += dt v carries
   out and the pair style's relative velocities see (sign +1); the next step
   takes back what was added (sign -1), kept per atom in `stream`, which
   migrates with its atom and is written to restart files */
void FixServoBC::remap_pass(const double *M, const double *origin, int sign)
{
  const int nlocal = atom->nlocal, *mask = atom->mask;
  const double dt = update->dt;
  if (sign < 0 && !streaming) return;
  for (int i = 0; i < nlocal; i++) {
    if (sign < 0) {
      for (int c = 0; c < dim; c++) atom->v[i][c] -= stream[i][c], stream[i][c] = 0.0;
      continue;
    }
    if (!(mask[i] & interior_bit)) continue;
    double u[3];
    sbc_remap_displacement(dim, M, origin, atom->x[i], u);
    for (int c = 0; c < dim; c++) stream[i][c] = u[c] / dt, atom->v[i][c] += stream[i][c];
  }
  streaming = sign > 0;
}

/* damping fire: the interior's sums of fire_damping.h on this rank */
void FixServoBC::fire_pass(double *local)
{
  for (int k = 0; k < SBC_FIRE_SUMS; k++) local[k] = 0.0;
  if (atom->nlocal == 0) return;    // the per-atom arrays may not exist yet
  if (dim == 3) fire_loop<3>(local);
  else fire_loop<2>(local);
}

/* fire_pass with the dimension a compile-time constant (the loops unroll) */
template <int DIM> void FixServoBC::fire_loop(double *local)
{
  constexpr int Z = DIM == 3 ? 0 : 2;    // rotations: z alone in 2d
  const int nlocal = atom->nlocal, *mask = atom->mask, bit = interior_bit;
  const double *v = &atom->v[0][0], *omega = &atom->omega[0][0], *f = &atom->f[0][0], *torque = &atom->torque[0][0];
  double sums[SBC_FIRE_SUMS] = {};    // in registers: local might alias the atoms' arrays
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & bit) sbc_fire_add(sums, DIM, &f[3 * i], &v[3 * i], &torque[3 * i + Z], &omega[3 * i + Z]);
  for (int k = 0; k < SBC_FIRE_SUMS; k++) local[k] += sums[k];
}

/* local damping (eq. 10) on the interior's forces, or FIRE's mix (mix not
   NULL) on its velocities v^(n-1/2), which the integrator's two half kicks
   then advance exactly as the core's engine does (fire_damping.h); out: its
   Ek (J) and the largest |net contact force| before damping (N, relax.h);
   again: the setup of a later run revisits the last step, whose rotation is
   counted and whose mix is applied */
void FixServoBC::interior_pass(bool again, const sbc_fire_mix *mix, double out[2])
{
  out[0] = out[1] = 0.0;
  if (atom->nlocal == 0) return;    // the per-atom arrays may not exist yet
  const bool local = settings.damping == SBC_DAMPING_LOCAL;
  if (dim == 3) local ? interior_loop<3, true>(again, mix, out) : interior_loop<3, false>(again, mix, out);
  else local ? interior_loop<2, true>(again, mix, out) : interior_loop<2, false>(again, mix, out);
}

/* interior_pass with the dimension and eq. 10 as compile-time constants: the
   loops over components unroll, and without local damping (FIRE, none) eq.
   10 is not evaluated (with alpha = 0 it leaves every force as it is) */
template <int DIM, bool LOCAL> void FixServoBC::interior_loop(bool again, const sbc_fire_mix *mix, double out[2])
{
  constexpr int NROT = DIM == 3 ? 3 : 1, Z = DIM == 3 ? 0 : 2;    // rotations: z alone in 2d
  const int nlocal = atom->nlocal, *mask = atom->mask, bit = interior_bit;
  // flat views of the contiguous per-atom arrays
  double *v = &atom->v[0][0], *omega = &atom->omega[0][0];
  // per_atom: rows of 1 + NROT (a contiguous LAMMPS array), the rotations after the flag
  double *f = &atom->f[0][0], *torque = &atom->torque[0][0], *turned = &per_atom[0][1];
  const double *radius = atom->radius, *rmass = atom->rmass, dt = update->dt;
  const double alpha = settings.alpha, beta = settings.beta;
  // I = inertia m r^2: the integrator's disc (2d) or sphere (3d, 2/5)
  const double inertia = DIM == 3 ? 0.4 : servo_bc_host::inertia, turn = again ? 0.0 : dt;
  const bool stopping = mix && mix->stop != 0.0;
  double ek = 0.0, net = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & bit)) continue;
    double *fi = &f[3 * i], *ti = &torque[3 * i + Z], *vi = &v[3 * i], *wi = &omega[3 * i + Z];
    const double m = rmass[i], I = inertia * m * radius[i] * radius[i], inv = dt / (m * I);
    double v0[DIM], w0[NROT], vk[DIM], wk[NROT], f2 = 0.0;
    int loaded = 0;
    if (mix) {    // the stop's half kicks (two divisions) only on the step that stops: otherwise push, spin as mixed
      const double push = stopping ? sbc_fire_factor(mix->push, mix, dt / m) : mix->push;
      const double spin = stopping ? sbc_fire_factor(mix->spin, mix, dt / I) : mix->spin;
      for (int c = 0; c < DIM; c++) vi[c] = sbc_fire_velocity(mix, push, vi[c], fi[c]);
      for (int c = 0; c < NROT; c++) wi[c] = sbc_fire_velocity(mix, spin, wi[c], ti[c]);
    }
    for (int c = 0; c < DIM; c++) v0[c] = vi[c], f2 += fi[c] * fi[c];
    for (int c = 0; c < NROT; c++) w0[c] = wi[c];
    net = std::max(net, f2);
    if (LOCAL) {    // eq. 10, with the half-step velocities (no damping at v = 0)
      for (int c = 0; c < DIM; c++) fi[c] = sbc_damp_local(fi[c], v0[c], alpha);
      for (int c = 0; c < NROT; c++) ti[c] = sbc_damp_local(ti[c], w0[c], beta);
    }
    // Ek and the rotation with the velocities after this step's kick
    // (v^(n+1/2) = v^(n-1/2) + dt f/m), as the embedded engine measures them;
    // one division: 1/m = I/(m I), 1/I = m/(m I)
    for (int c = 0; c < DIM; c++) vk[c] = v0[c] + fi[c] * I * inv, loaded |= fi[c] != 0.0;
    for (int c = 0; c < NROT; c++) wk[c] = w0[c] + ti[c] * m * inv, loaded |= ti[c] != 0.0;
    for (int c = 0; c < NROT; c++) turned[(1 + NROT) * i + c] += turn * wk[c];
    // a contact-free atom (a rattler) is left out of Ek, as in the core (relax.h)
    if (loaded) ek += sbc_kinetic_energy(DIM, m, I, vk, wk);
  }
  out[0] = ek;
  out[1] = std::sqrt(net);
}

/* eq. 12 over the pair style's own half list and its shear history: per
   contact kn dn^2/2 + kt |shear|^2/2 (the stored shear is the elastic one,
   rescaled at the Coulomb limit); also sum dn / Rbar, the contact count
   (eq. 39) and the sum of |contact force| = |(kn dn, kt shear)| (relax.h). Each contact once: with newton pair off an owned-ghost pair stands
   on both ranks, and the lower tag counts it. */
void FixServoBC::contact_pass(double out[4])
{
  if (contacts) {    // the core's sums over this rank's pairs, each pair on the rank of its end A
    contacts->contact_sums(out);
    out[0] += seal_energy;
    return;
  }
  const int nlocal = atom->nlocal, *mask = atom->mask, newton = force->newton_pair;
  const tagint *tag = atom->tag;
  double **x = atom->x;
  const double *radius = atom->radius;
  NeighList *list = law.list();
  double **history = law.history();
  const double kn = law.kn, kt = law.kt;
  double ep = 0.0, ov = 0.0, nc = 0.0, fc = 0.0;
  for (int ii = 0; ii < list->inum; ii++) {
    int i = list->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    int *jlist = list->firstneigh[i], jnum = list->numneigh[i];
    const double *shear_i = history ? history[i] : nullptr;
    for (int jj = 0; jj < jnum; jj++) {
      int j = jlist[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      if (j >= nlocal && !newton && tag[j] < tag[i]) continue;
      double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1], rs = radius[i] + radius[j];
      double d2 = dx * dx + dy * dy;
      if (dim == 3) d2 += (x[j][2] - x[i][2]) * (x[j][2] - x[i][2]);
      if (d2 >= rs * rs) continue;
      double dn = rs - std::sqrt(d2);
      double s2 = 0.0;
      if (shear_i) {
        const double *sh = &shear_i[law.stride * jj + law.offset];
        s2 = sh[0] * sh[0] + sh[1] * sh[1] + sh[2] * sh[2];
      }
      ep += 0.5 * kn * dn * dn + 0.5 * kt * s2;
      fc += std::sqrt(kn * kn * dn * dn + kt * kt * s2);
      ov += dn / (0.5 * rs);
      nc += 1.0;
    }
  }
  out[0] = ep + seal_energy;
  out[1] = ov;
  out[2] = nc;
  out[3] = fc;
}

/* frame positions, reactions and rotations in frame order, plus sum |theta|
   and the particle count (eq. 41), this rank's share, into buf (driver.h's
   layout, zeroed) */
void FixServoBC::frame_pass(double *buf)
{
  const int nlocal = atom->nlocal, Q = frame.n, *mask = atom->mask;
  double **x = atom->x, **f = atom->f, **torque = atom->torque;
  double rot = 0.0, npart = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (mask[i] & frame_bit) {
      int q = slot[atom->tag[i]];
      for (int c = 0; c < dim; c++) {
        buf[3 * q + c] = x[i][c];
        buf[3 * Q + 3 * q + c] = f[i][c];
      }
      for (int c = 0; c < nrot; c++) {
        buf[SBC_DRIVER_TORQUE(dim, Q) + nrot * q + c] = torque[i][zrot + c];
        buf[SBC_DRIVER_THETA(dim, Q) + nrot * q + c] = per_atom[i][1 + c];
      }
    }
    rot += nrot == 1 ? std::fabs(per_atom[i][1]) : std::sqrt(per_atom[i][1] * per_atom[i][1] +
                                                             per_atom[i][2] * per_atom[i][2] +
                                                             per_atom[i][3] * per_atom[i][3]);
    npart += 1.0;
  }
  for (int k = 0; k < 3 * Q && seal_on; k++) buf[3 * Q + k] += seal_reaction[k];
  buf[SBC_DRIVER_SUMS(dim, Q)] = rot;
  buf[SBC_DRIVER_SUMS(dim, Q) + 1] = npart;
}

/* confine.h on the owned interior atoms against the frame's present centres
   fx; the smallest failing atom ID over all ranks names the error, on every rank */
int FixServoBC::confined(const double *fx, int increment, char *message, size_t cap)
{
  const int nlocal = atom->nlocal, *mask = atom->mask;
  double **x = atom->x, **v = atom->v;
  long bad = LONG_MAX, first;
  char mine_text[SBC_ERROR_LEN] = "";
  sbc_error err;
  sbc_confine prepared;
  sbc_confine_prepare(&prepared, &frame, fx);
  for (int i = 0; i < nlocal; i++) {
    const long id = (long) atom->tag[i];
    if (!(mask[i] & interior_bit) || id >= bad) continue;
    if (sbc_confine_check(&prepared, increment, id, x[i], v[i], &err) != SBC_OK) {
      bad = id;
      std::snprintf(mine_text, sizeof mine_text, "%s", err.message);
    }
  }
  MPI_Allreduce(&bad, &first, 1, MPI_LONG, MPI_MIN, world);
  if (first == LONG_MAX) return 0;
  int mine = bad == first ? comm->me : comm->nprocs, root;
  MPI_Allreduce(&mine, &root, 1, MPI_INT, MPI_MIN, world);
  MPI_Bcast(mine_text, (int) sizeof mine_text, MPI_CHAR, root, world);
  std::snprintf(message, cap, "%s", mine_text);
  return SBC_ERR_GEOMETRY;
}

/* a converged increment: its row in the results file (rank 0) and the log line */
void FixServoBC::write_row(const char *line)
{
  sbc_error err;
  if (comm->me == 0 && csv.fp && sbc_csv_write(&csv, sbc_controller_result(ctl), &err) != SBC_OK)
    fail_here(err.message);
  log("%s\n", line);
}

/* damping, then what the controller asks for (driver.h: Ek every step, Ep and
   the contact sums when the criterion needs them, the frame when the
   relaxation ends), the controller step, the confinement check, the row */
void FixServoBC::post_force(int)
{
  if (finished) return;
  // the setup of a later run (or of a restarted one) sees the configuration of
  // the last step again: the controller has already taken it
  const bool again = update->ntimestep == last_step;
  seal_pass();
  sbc_error err;
  sbc_event ev = sbc_driver_step(driver, again, &err);
  if (again) return;
  last_step = update->ntimestep;
  if (ev == SBC_EVENT_FAILED) fail(err.message);
  if (ev == SBC_EVENT_CORRECTED || ev == SBC_EVENT_INCREMENT) frame_still = 0;
  if (ev == SBC_EVENT_INCREMENT || ev == SBC_EVENT_FINISHED) {
    last = *sbc_controller_result(ctl);
    clock_reported = MPI_Wtime();
  } else if (comm->me == 0) {    // the clock on every step: 1000 steps of 10^6 discs take 110 s
    progress();
  }
  if (ev == SBC_EVENT_FINISHED) {
    finished = 1;
    servo_bc_host::end_run(lmp);
  }
}

double FixServoBC::compute_vector(int n)
{
  // the layout is the core's (columns.h: result columns by name, then the increment under way)
  return sbc_thermo_value(ctl, &last, finished, n);
}

/* per_atom: the frame flag and the accumulated rotation (nrot components);
   stream: the velocity of keyword remap x to be taken back (remap_pass) */
void FixServoBC::grow_arrays(int nmax)
{
  memory->grow(per_atom, nmax, 1 + nrot, "servo_bc:per_atom");
  memory->grow(stream, nmax, 3, "servo_bc:stream");
  for (; stream_rows < nmax; stream_rows++)    // an atom's slots are zero until a remap fills them
    for (int c = 0; c < 3; c++) stream[stream_rows][c] = 0.0;
  array_atom = per_atom;
}

void FixServoBC::copy_arrays(int i, int j, int)
{
  for (int c = 0; c <= nrot; c++) per_atom[j][c] = per_atom[i][c];
  for (int c = 0; c < 3; c++) stream[j][c] = stream[i][c];
}

int FixServoBC::pack_exchange(int i, double *out)
{
  for (int c = 0; c <= nrot; c++) out[c] = per_atom[i][c];
  for (int c = 0; c < 3; c++) out[1 + nrot + c] = stream[i][c];
  return 1 + nrot + 3;
}

int FixServoBC::unpack_exchange(int nlocal, double *in)
{
  for (int c = 0; c <= nrot; c++) per_atom[nlocal][c] = in[c];
  for (int c = 0; c < 3; c++) stream[nlocal][c] = in[1 + nrot + c];
  return 1 + nrot + 3;
}

/* every error of this fix: "Fix servo_bc: " and the message, on all ranks
   (fail) or on this rank alone (fail_here, which aborts the others). The text
   lives in a member: the host may read it while it tears the job down. */
void FixServoBC::fail(const std::string &message)
{
  last_error = "Fix servo_bc: " + message;
  error->all(FLERR, last_error.c_str());
}

void FixServoBC::fail_here(const std::string &message)
{
  last_error = "Fix servo_bc: " + message;
  if (!servo_bc_host::one_writes_log && logfile) {
    fprintf(logfile, "ERROR on proc %d: %s\n", comm->me, last_error.c_str());
    fflush(logfile);
  }
  error->one(FLERR, last_error.c_str());
}

/* rank 0: the progress line of a long increment, SBC_PROGRESS_EVERY s after
   the last line or row (LAMMPS' thermo stays as it was while the frame relaxes) */
void FixServoBC::progress()
{
  const double now = MPI_Wtime();
  if (now - clock_reported < SBC_PROGRESS_EVERY) return;
  clock_reported = now;
  char line[256];
  sbc_controller_progress_line(ctl, (long) update->ntimestep, now - clock_start, line, sizeof line);
  log("servo_bc:   %s\n", line);
}

/* a line on screen and in the log file, from rank 0 */
void FixServoBC::log(const char *format, ...)
{
  if (comm->me != 0) return;
  char line[512];
  va_list args;
  va_start(args, format);
  vsnprintf(line, sizeof line, format, args);
  va_end(args);
  if (screen) fputs(line, screen);
  if (logfile) fputs(line, logfile);
}
