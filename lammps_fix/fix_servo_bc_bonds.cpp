/* ----------------------------------------------------------------------
   fix servo_bc/bonds (see fix_servo_bc_bonds.h):
     fix ID group servo_bc/bonds MODEL E nu alpha [strength FT FS MB MT] [friction MU] [breaks FILE]   (3D)
     fix ID group servo_bc/bonds cohesive kn KN ks KS kr KR fn FN fs FS mr MR mu MU   (2D)
   MODEL = beam (Timoshenko beams, E_b = E Pa, nu_b = nu) or parallel
   (parallel bonds, k^n = E / 2 r_min, k^s = k^n / 4.2); bond radius
   alpha r_min; with a strength a bond breaks when eq. 8 in 3D reaches 1
   (bpm_bond.h) and becomes a frictional contact (friction MU). cohesive: the paper's eqs. 7-8 with Table 6's quantities
   (N/m, N/m, N m/rad, N, N, N m, -), eq. 6 after failure and between
   discs that were apart. Bonds join the group's particles that touch at the
   first run. breaks FILE writes a row
   per broken bond (step,id_a,id_b,x,y,z: the midpoint of its centres, m).
   Outputs: f_ID (scalar) the bonds' strain energy (J, eq. 50 or the beams'
   1/2 u K u; cohesive: eq. 12's Ep of every contact, bonds included);
   f_ID[1] the intact bond count; f_ID[2] eq. 48's critical time step (s;
   cohesive: the bonds formed). Beam and parallel also keep the thesis'
   energy balance: f_ID[3] the kinetic energy of the group (eq. 49, the
   host's full-step velocities and inertia 2/5 m r^2), f_ID[4] what the
   bonds dissipated (eq. 51: the energy broken bonds held, friction in their
   contacts; no dashpots here), f_ID[5] the work of every other force and
   moment on the group since the first run (eq. 52, trapezoidal: loads,
   supports, damping fixes), f_ID[6] eq. 53's
   |W_kin + W_int + W_dis - W_ext| / max(|terms|).
------------------------------------------------------------------------- */

#include "fix_servo_bc_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "pair.h"
#include "group.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "update.h"

#include <cstdint>
#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixServoBCBonds::FixServoBCBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), E(0.0), nu(0.0), alpha(0.0), strength{0.0, 0.0, 0.0, 0.0, 0.0}, failure(false), kn(0.0),
    bonds(nullptr), n(0), dim(3), reported(-1), pairs_counted(0), have_contacts(false), contact_mine{0.0, 0.0, 0.0, 0.0}, intact_mine(0),
    rmin(0.0), maxb(0), per(0),
    width(0), critical_dt(0.0), formed(0), slot(nullptr), carry(nullptr), step_load(nullptr), step_motion(nullptr), partner_at(nullptr), partner_slot(nullptr), slot_load(nullptr),
    nmax_slots(0), have_prev(false), restarted(false), copies_stale(false), longest(0.0), reduced_at(-1), sums{0.0, 0.0, 0.0, 0.0, 0.0},
    kinetic_mine(0.0), breaks_fp(nullptr)
{
  law = sbc_cohesive_default();
  if (narg < 4) fail("expected a model after the style (beam, parallel or cohesive)");
  model = arg[3];
  if (model == "cohesive") {
    dim = 2;
    sbc_error err;
    if (sbc_cohesive_parse(narg - 4, arg + 4, "cohesive", &law, &err) != SBC_OK) fail(err.message);
    kn = law.kn;
  } else {
    if (model != "beam" && model != "parallel")
      fail("model '" + model + "' is not valid (expected beam, parallel or cohesive)");
    if (narg < 7)
      fail(std::string("expected at least 4 arguments after the style (MODEL E nu alpha), got ") +
           std::to_string(narg - 3));
    const char *names[3] = {"E", "nu", "alpha"};
    double *values[3] = {&E, &nu, &alpha};
    for (int k = 0; k < 3; k++) *values[k] = number(names[k], arg[4 + k]);
    if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5) || !(alpha > 0.0))
      fail("E " + std::string(arg[4]) + ", nu " + arg[5] + ", alpha " + arg[6] +
           " (expected E > 0 Pa, -1 < nu < 0.5, alpha > 0)");
    // optional failure, the runner's words: strength FT FS MB MT, friction MU
    bool have_strength = false, have_friction = false;
    for (int k = 7; k < narg;) {
      const std::string key = arg[k];
      if ((key == "strength" && have_strength) || (key == "friction" && have_friction) ||
          (key == "breaks" && !breaks_file.empty()))
        fail("keyword " + key + " given twice (each keyword once)");
      if (key == "strength") {
        have_strength = true;
        if (k + 4 >= narg)
          fail("keyword strength needs 4 values (FT FS MB MT: tension N, shear N, bending N m, twisting N m)");
        const char *what[4] = {"strength FT", "strength FS", "strength MB", "strength MT"};
        for (int q = 0; q < 4; q++) strength[q] = number(what[q], arg[k + 1 + q]);
        if (!(strength[0] > 0.0) || !(strength[1] >= 0.0) || !(strength[2] >= 0.0) || !(strength[3] >= 0.0))
          fail(std::string("keyword strength: ") + arg[k + 1] + " " + arg[k + 2] + " " + arg[k + 3] + " " + arg[k + 4] +
               " (expected a tension > 0 and shear, bending, twisting >= 0; 0 leaves a term out)");
        failure = true;
        k += 5;
      } else if (key == "friction") {
        have_friction = true;
        if (k + 1 >= narg) fail("keyword friction needs a value (MU)");
        strength[4] = number("friction", arg[k + 1]);
        if (!(strength[4] >= 0.0)) fail(std::string("keyword friction: ") + arg[k + 1] + " (expected >= 0)");
        k += 2;
      } else if (key == "breaks") {
        if (k + 1 >= narg) fail("keyword breaks needs a file name");
        breaks_file = arg[k + 1];
        if (breaks_file.empty()) fail("keyword breaks: an empty file name");
        k += 2;
      } else
        fail("unknown keyword '" + key + "' (expected strength, friction or breaks)");
    }
  }
  if (!atom->sphere_flag) fail("requires atom_style sphere");
  if (std::strcmp(update->unit_style, "si") != 0)
    fail(std::string("requires units si (the laws' quantities are SI; this script has units ") + update->unit_style +
         ")");
  if (domain->dimension != dim)
    fail(dim == 3 ? "requires a 3d box (the bond models are 3D)"
                  : "cohesive requires a 2d box (the paper's cohesive bonds are 2D: dimension 2)");
  restart_global = 1;
  // the pairs' per-atom slots
  restart_peratom = 1;
  comm_forward = 6;
#ifndef SERVO_BC_LIGGGHTS
  maxexchange = 9;            // the 8 carried values and a count of 0 until the bonds form (size_slots)
  maxexchange_dynamic = 1;
#endif
  grow_arrays(atom->nmax);
  atom->add_callback(0);    // Atom::GROW
  atom->add_callback(1);    // Atom::RESTART
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = dim == 3 ? 6 : 2;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

FixServoBCBonds::~FixServoBCBonds()
{
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(slot);
  memory->destroy(carry);
  memory->destroy(step_load);
  memory->destroy(step_motion);
  memory->destroy(partner_at);
  memory->destroy(partner_slot);
  memory->destroy(slot_load);
  if (breaks_fp) fclose(breaks_fp);
  sbc_bpm_free(bonds);
}

int FixServoBCBonds::setmask() { return PRE_EXCHANGE | POST_FORCE | POST_RUN | END_OF_STEP; }

/* atoms are about to migrate: each pair's copies alike first */
void FixServoBCBonds::pre_exchange()
{
  if (bonds) sync_copies();
  if (have_contacts) sync_contacts();
}

/* how many bonds are left, at the end of a run where some broke */
void FixServoBCBonds::post_run()
{
  if (bonds) sync_copies();    // any command after the run may move the atoms
  if (have_contacts) sync_contacts();
  if (!have_contacts && !(bonds && failure)) return;
  reduce_outputs();
  const int intact = (int) sums[1], initial = formed;
  if (intact == reported) return;
  reported = intact;
  char line[128];
  std::snprintf(line, sizeof line, "fix servo_bc/bonds: %s bonds intact %d of %d\n", model.c_str(), intact, initial);
  say(line);
}

/* one line on rank 0's screen and log */
void FixServoBCBonds::say(const char *line)
{
  if (comm->me != 0) return;
  if (screen) fputs(line, screen);
  if (logfile) fputs(line, logfile);
}

/* a finite number or a message naming the keyword */
double FixServoBCBonds::number(const char *keyword, const char *word)
{
  char *end = nullptr;
  const double v = std::strtod(word, &end);
  if (end == word || *end != '\0' || !std::isfinite(v))
    fail(std::string("keyword ") + keyword + ": '" + word + "' is not a number");
  return v;
}

void FixServoBCBonds::fail(const std::string &message)
{
  last_error = "Fix servo_bc/bonds: " + message;    // kept: LIGGGHTS' error->all takes a C string
  error->all(FLERR, last_error.c_str());
}

/* an error only this rank sees (it aborts the others) */
void FixServoBCBonds::fail_here(const std::string &message)
{
  last_error = "Fix servo_bc/bonds: " + message;
  error->one(FLERR, last_error.c_str());
}

void FixServoBCBonds::init()
{
  // cohesive: the core computes every contact; a pair style that does too counts them twice
  if (model == "cohesive" && force->pair && !force->pair_match("zero", 1))
    fail(std::string("cohesive computes every contact between the group's discs; pair_style ") + force->pair_style +
         " computes them again (use pair_style zero in LAMMPS, pair_style none in LIGGGHTS)");
  // beam | parallel: bonded spheres interact through their bond alone, a broken bond through its contact
  // (thesis Sect. 3); a pair style adds its own contact force between them when they overlap
  if (model != "cohesive" && force->pair && !force->pair_match("zero", 1) && comm->me == 0)
    error->warning(FLERR, (std::string("Fix servo_bc/bonds: pair_style ") + force->pair_style +
                           " also acts between bonded spheres: where they overlap, its contact force adds to the "
                           "bond's (and to a broken bond's contact)").c_str());
  // one fix servo_bc/bonds per atom: a second one on the same atoms would bond them twice
  for (int f = 0; f < modify->nfix; f++) {
    Fix *other = modify->fix[f];
    if (other == this || std::strcmp(other->style, "servo_bc/bonds") != 0) continue;
    int shared = 0, total = 0;
    for (int i = 0; i < atom->nlocal; i++) shared += (atom->mask[i] & groupbit) && (atom->mask[i] & other->groupbit);
    MPI_Allreduce(&shared, &total, 1, MPI_INT, MPI_SUM, world);
    if (total)
      fail(std::string("fix ") + other->id + " (servo_bc/bonds, group " + group->names[other->igroup] + ") bonds " +
           std::to_string(total) + " of this fix's atoms (group " + group->names[igroup] +
           ") too, which would bond them twice; one fix servo_bc/bonds per atom");
  }
  // fix balance moves atoms in its pre_exchange: the bonds' copies must be alike before
  for (int f = 0; f < modify->nfix && modify->fix[f] != this; f++)
    if (std::strcmp(modify->fix[f]->style, "balance") == 0)
      fail(std::string("fix ") + modify->fix[f]->id + " (balance) comes before this fix; define fix " + id +
           " first (bonds whose atoms a rank owns keep one copy current until atoms migrate, in pre_exchange)");
}

namespace {
// marks fix servo_bc/bonds' restart block (bump on any change of its layout);
// the bonds' states moved into per-atom data with the layout after BONDS_GATHERED;
// the cohesive contacts' states, with model COHESIVE after COHESIVE_GATHERED
const double BONDS_MAGIC = 8.020007e7, BONDS_UNSEALED = 8.020006e7, BONDS_GATHERED = 8.020005e7;
const int COHESIVE_GATHERED = 3, COHESIVE = 4;
}

/* rank 0: the marker, the seal's head (the block's length, its seal, the checksum of what follows: sbc/saved.h), then
   beam | parallel: model (1 | 2), E, nu, alpha, failure, strength[5], r_min,
   slots per atom, doubles per bond state, eq. 48's step, the bonds formed,
   the spheres, the longest bond at creation (the bonds' states are per-atom
   data: pack_restart);
   cohesive: model 4, the law (kn ks kr fn fs mr mu), r_min, slots per
   atom, the bonds formed, the discs (the pairs' states are per-atom data) */
void FixServoBCBonds::write_restart(FILE *fp)
{
  if (bonds) sync_copies();    // every rank, before its per-atom data are packed
  if (have_contacts) sync_contacts();
  if (comm->me != 0 || (!bonds && !have_contacts)) return;
  std::vector<double> list;
  if (have_contacts) {
    list = {BONDS_MAGIC, 0.0, 0.0, 0.0, (double) COHESIVE, law.kn, law.ks, law.kr, law.fn_u, law.fs_u, law.m_u, law.mu,
            rmin, (double) maxb, (double) formed, (double) n};
  } else {
    list = {BONDS_MAGIC, 0.0, 0.0, 0.0, model == "beam" ? 1.0 : 2.0, E, nu, alpha, failure ? 1.0 : 0.0};
    list.insert(list.end(), strength, strength + 5);
    list.insert(list.end(),
                {rmin, (double) maxb, (double) per, critical_dt, (double) formed, (double) n, longest});
  }
  sbc_saved_seal(&list[1], list.size() - 1);
  int size = (int) (list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

/* every count, index and value checked before it is used (sbc/saved.h): a
   restart file may be truncated, corrupted or from another version */
void FixServoBCBonds::restart(char *raw)
{
  const double *list = (const double *) raw;
  sbc_error err;
  sbc_saved rd;
  if (list[0] == BONDS_GATHERED)
    fail("restart: this file's fix servo_bc/bonds block is from a version that kept every bond on every rank; "
         "this version keeps each bond with its atoms and cannot read it (run the loading again from its data "
         "file, or read the file with the version that wrote it)");
  if (list[0] != BONDS_MAGIC)
    fail(std::string("restart: this fix's block in the restart file is not this version's fix servo_bc/bonds'") +
         (list[0] == BONDS_UNSEALED ? " (an earlier 0.3.0 block, without its seal)" : "") +
         " (write the restart file again)");
  size_t sealed = 0;
  if (sbc_saved_open(list + 1, SIZE_MAX, &sealed, "restart: fix servo_bc/bonds data", &err) != SBC_OK)
    fail(err.message);
  const long total = (long) sealed + 1;    // with the marker
  sbc_saved_start(&rd, list + 1 + SBC_SEALED_HEAD, sealed - SBC_SEALED_HEAD, "restart data", &err);
  const int code = (int) sbc_saved_int(&rd, "model", 1, COHESIVE);
  if (rd.st != SBC_OK) fail(err.message);
  if (code == COHESIVE_GATHERED)
    fail("restart: this file's fix servo_bc/bonds cohesive block is from a version that kept every contact on "
         "every rank; this version keeps each contact with its atoms and cannot read it (run the loading again "
         "from its data file, or read the file with the version that wrote it)");
  const std::string saved_model = code == 1 ? "beam" : code == 2 ? "parallel" : "cohesive";
  if (saved_model != model && (saved_model == "cohesive" || model == "cohesive"))
    fail("restart: the file's bonds are " + saved_model + "; this fix asks for " + model);
  if (model == "cohesive") {
    double saved_law[7];
    const char *names[7] = {"kn", "ks", "kr", "fn", "fs", "mr", "mu"};
    const double mine[7] = {law.kn, law.ks, law.kr, law.fn_u, law.fs_u, law.m_u, law.mu};
    std::string differ;
    for (int q = 0; q < 7; q++) {
      saved_law[q] = sbc_saved_real(&rd, names[q]);
      if (rd.st == SBC_OK && saved_law[q] != mine[q])
        differ += std::string(differ.empty() ? "" : ", ") + names[q] + " " + std::to_string(saved_law[q]) +
                  " (this fix: " + std::to_string(mine[q]) + ")";
    }
    if (rd.st != SBC_OK) fail(err.message);
    if (!differ.empty())
      fail("restart: the file's cohesive law differs: " + differ + "; define the fix with the saved law");
    rmin = sbc_saved_positive(&rd, "smallest radius");
    maxb = (int) sbc_saved_int(&rd, "slots per atom", 1, 1000);
    formed = (int) sbc_saved_int(&rd, "bonds formed", 1, 2000000000L);
    n = (int) sbc_saved_int(&rd, "disc count", 2, 2000000000L);
    if (rd.st != SBC_OK) fail(err.message);
    if ((long) rd.at != total - 1 - SBC_SEALED_HEAD)
      fail("restart: the block holds " + std::to_string(total) + " values, its contents " + std::to_string(rd.at + 1 + SBC_SEALED_HEAD));
    per = SBC_COHESIVE_PAIR_STATE;
    size_slots();
    have_contacts = true;
    restarted = true;
    return;
  }
  double saved_params[3], saved_strength[5];
  const char *pnames[3] = {"E", "nu", "alpha"}, *snames[5] = {"FT", "FS", "MB", "MT", "MU"};
  for (int q = 0; q < 3; q++) saved_params[q] = sbc_saved_real(&rd, pnames[q]);
  const bool saved_failure = sbc_saved_int(&rd, "failure", 0, 1) != 0;
  for (int q = 0; q < 5; q++) saved_strength[q] = sbc_saved_real(&rd, snames[q]);
  if (rd.st != SBC_OK) fail(err.message);
  bool same = saved_model == model && saved_params[0] == E && saved_params[1] == nu && saved_params[2] == alpha &&
              saved_failure == failure;
  for (int q = 0; q < 5 && same && failure; q++) same = saved_strength[q] == strength[q];
  if (!same)
    fail("restart: the file's bonds are " + saved_model + " " + std::to_string(saved_params[0]) + " " +
         std::to_string(saved_params[1]) + " " + std::to_string(saved_params[2]) +
         (saved_failure ? " with a strength" : "") +
         "; this fix asks for other ones (model, E, nu, alpha, strength and friction must be the same)");
  rmin = sbc_saved_positive(&rd, "smallest radius");
  maxb = (int) sbc_saved_int(&rd, "slots per atom", 1, 1000);
  per = (int) sbc_saved_int(&rd, "doubles per bond", 1, 256);
  critical_dt = sbc_saved_positive(&rd, "critical time step");
  formed = (int) sbc_saved_int(&rd, "bonds formed", 1, 2000000000L);
  n = (int) sbc_saved_int(&rd, "sphere count", 2, 2000000000L);
  longest = sbc_saved_positive(&rd, "longest bond");
  if (rd.st != SBC_OK) fail(err.message);
  if ((long) rd.at != total - 1 - SBC_SEALED_HEAD)
    fail("restart: the block holds " + std::to_string(total) + " values, its contents " + std::to_string(rd.at + 1 + SBC_SEALED_HEAD));
  char msg[512] = "";
  bonds = sbc_bpm_host_law(model.c_str(), E, nu, alpha, failure ? strength : nullptr, rmin, msg, sizeof msg);
  if (!bonds) fail(std::string("restart: ") + msg);
  if (per != sbc_bpm_host_state_doubles(bonds))
    fail("restart: " + std::to_string(per) + " doubles per bond state; this version's " + model + " bonds have " +
         std::to_string(sbc_bpm_host_state_doubles(bonds)));
  size_slots();
  restarted = true;
}

void FixServoBCBonds::setup(int)
{
  if (dim == 2) {
    if (!have_contacts) create_contacts();    // the first run: the group's touching discs
    else build_contacts(false);
    step_contacts(false);    // the last configuration again: no motion, the same loads
    return;
  }
  if (!bonds) create_slots();    // the first run: the group's touching spheres
  map_partners();
  step_slots(false);             // the last configuration again: no motion, the same loads
}

/* the bonds' loads: the motion of the step just taken is dt v(t + dt/2)
   (velocity Verlet: v is at the half step here) */
void FixServoBCBonds::post_force(int)
{
  if (dim == 2) {
    if (neighbor->ago == 0) build_contacts(false);
    step_contacts(true);
    return;
  }
  if (neighbor->ago == 0) map_partners();
  step_slots(true);
}

void FixServoBCBonds::contact_sums(double out[4]) const { std::copy(contact_mine, contact_mine + 4, out); }

double FixServoBCBonds::compute_scalar()
{
  if (!bonds && !have_contacts) return 0.0;
  reduce_outputs();
  return sums[0];
}

double FixServoBCBonds::compute_vector(int k)
{
  if (!bonds && !have_contacts) return 0.0;
  if (have_contacts) {
    reduce_outputs();
    return k == 0 ? sums[1] : formed;
  }
  if (k == 1) return critical_dt;
  reduce_outputs();
  const double u = sums[0], kinetic = sums[2], d = sums[3], external_work = sums[4];
  switch (k) {
    case 0: return sums[1];
    case 2: return kinetic;
    case 3: return d;
    case 4: return external_work;
    default: {    // eq. 53
      double big = std::max(std::fabs(kinetic), std::max(std::fabs(u), std::fabs(external_work)));
      big = std::max(big, std::fabs(d));
      return big > 0.0 ? std::fabs(kinetic + u + d - external_work) / big : 0.0;
    }
  }
}

void FixServoBCBonds::end_of_step()
{
  if (!bonds) return;
  energy_slots();
  if (failure && !breaks_file.empty()) write_breaks();
}
