/* ----------------------------------------------------------------------
   fix servo_bc/bonds (see fix_servo_bc_bonds.h):
     fix ID group servo_bc/bonds MODEL E nu alpha [strength FT FS MB MT] [friction MU]   (3D)
     fix ID group servo_bc/bonds cohesive kn KN ks KS kr KR fn FN fs FS mr MR mu MU   (2D)
   MODEL = beam (Timoshenko beams, E_b = E Pa, nu_b = nu) or parallel
   (parallel bonds, k^n = E / 2 r_min, k^s = k^n / 4.2); bond radius
   alpha r_min; with a strength a bond breaks when eq. 8 in 3D reaches 1
   (bpm_bond.h) and becomes a frictional contact (friction MU). cohesive: the paper's eqs. 7-8 with Table 6's quantities
   (N/m, N/m, N m/rad, N, N, N m, -), eq. 6 after failure. Bonds join the
   group's particles that touch at the first run.
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
#include "modify.h"
#include "update.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixServoBCBonds::FixServoBCBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), E(0.0), nu(0.0), alpha(0.0), strength{0.0, 0.0, 0.0, 0.0, 0.0}, failure(false), kn(0.0),
    bonds(nullptr), contacts(nullptr), n(0), dim(3), last_step(-1), reported(-1), kinetic(0.0), external_work(0.0),
    have_prev(false)
{
  law = sbc_cohesive_default();
  if (narg < 4) fail("expected a model after the style (beam, parallel or cohesive)");
  model = arg[3];
  if (model == "cohesive") {
    // the words are checked by the core (sbc_cohesive_parse) when the fix is created
    for (int k = 4; k < narg; k++) words += std::string(k > 4 ? " " : "") + arg[k];
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
      if ((key == "strength" && have_strength) || (key == "friction" && have_friction))
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
      } else
        fail("unknown keyword '" + key + "' (expected strength or friction)");
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
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = dim == 3 ? 6 : 2;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

FixServoBCBonds::~FixServoBCBonds()
{
  sbc_bpm_free(bonds);
  sbc_cohesive_host_free(contacts);
}

int FixServoBCBonds::setmask() { return POST_FORCE | POST_RUN | END_OF_STEP; }

/* cohesive: how many bonds are left, at the end of a run where some broke */
void FixServoBCBonds::post_run()
{
  if (!contacts && !(bonds && failure)) return;
  const int intact = contacts ? sbc_cohesive_host_bond_count(contacts) : sbc_bpm_host_intact(bonds);
  if (intact == reported) return;
  reported = intact;
  char line[128];
  std::snprintf(line, sizeof line, "fix servo_bc/bonds: %s bonds intact %d of %d\n", model.c_str(), intact,
                contacts ? sbc_cohesive_host_bonds_initial(contacts) : sbc_bpm_host_bond_count(bonds));
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

void FixServoBCBonds::init()
{
  // cohesive: the core computes every contact; a pair style that does too counts them twice
  if (model == "cohesive" && force->pair && !force->pair_match("zero", 1))
    fail(std::string("cohesive computes every contact between the group's discs; pair_style ") + force->pair_style +
         " computes them again (use pair_style zero in LAMMPS, pair_style none in LIGGGHTS)");
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
  if (bonds || contacts) return;
  if (tags.empty()) create_bonds();    // cohesive: also from a restart file, at the present centres
  else bond_spheres();                 // from a restart file
}

namespace {
// marks fix servo_bc/bonds' restart block (bump on any change of its layout)
const double BONDS_MAGIC = 8.020005e7;
}

/* rank 0: the marker, the block's length, then
   beam | parallel: model (1 | 2), E, nu, alpha, failure, strength[5], n, the
   bond count nb, doubles per bond state, the reference spheres (ID, centre,
   radius, mass), every bond's state, W_ext of eq. 52, the fracture energy;
   cohesive: model 3, the law (kn ks kr fn fs mr mu), n, the atom IDs, the
   pair state's length and the pair state (cohesive_host.h) */
void FixServoBCBonds::write_restart(FILE *fp)
{
  if (comm->me != 0 || (!bonds && !contacts)) return;
  std::vector<double> list;
  if (contacts) {
    list = {BONDS_MAGIC, 0.0, 3.0, law.kn, law.ks, law.kr, law.fn_u, law.fs_u, law.m_u, law.mu, (double) n};
    for (int k = 0; k < n; k++) list.push_back((double) tags[k]);
    std::vector<double> state(sbc_cohesive_host_state_size(contacts));
    sbc_cohesive_host_state_get(contacts, state.data());
    list.push_back((double) state.size());
    list.insert(list.end(), state.begin(), state.end());
  } else {
    const int nb = sbc_bpm_host_bond_count(bonds), per = sbc_bpm_host_state_doubles(bonds);
    list = {BONDS_MAGIC, 0.0, model == "beam" ? 1.0 : 2.0, E, nu, alpha, failure ? 1.0 : 0.0};
    list.insert(list.end(), strength, strength + 5);
    list.insert(list.end(), {(double) n, (double) nb, (double) per});
    for (int k = 0; k < n; k++)
      list.insert(list.end(),
                  {(double) tags[k], ref_x[3 * k], ref_x[3 * k + 1], ref_x[3 * k + 2], ref_r[k], ref_m[k]});
    std::vector<double> state(per);
    for (int k = 0; k < nb; k++) {
      sbc_bpm_host_state_get(bonds, k, state.data());
      list.insert(list.end(), state.begin(), state.end());
    }
    list.push_back(external_work);    // eq. 52 so far
    list.push_back(sbc_bpm_host_fracture_energy(bonds));
  }
  list[1] = (double) list.size();
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
  if (list[0] != BONDS_MAGIC)
    fail("restart: this fix's block in the restart file is not this version's fix servo_bc/bonds' (write the "
         "restart file again)");
  sbc_saved_start(&rd, list + 1, 1, "restart data", &err);
  const long total = sbc_saved_int(&rd, "length", 4, 1000000000L);
  if (rd.st != SBC_OK) fail(err.message);
  sbc_saved_start(&rd, list + 2, (size_t) total - 2, "restart data", &err);
  const int code = (int) sbc_saved_int(&rd, "model", 1, 3);
  if (rd.st != SBC_OK) fail(err.message);
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
    const long count = sbc_saved_int(&rd, "particle count", 1, total);
    if (rd.st != SBC_OK) fail(err.message);
    saved_tags.assign(count, 0);
    for (long k = 0; k < count; k++) saved_tags[k] = (tagint) sbc_saved_int(&rd, "atom ID", 1, MAXTAGINT);
    const long size = sbc_saved_int(&rd, "pair state length", 0, total - 2 - (long) rd.at - 1);
    if (rd.st != SBC_OK) fail(err.message);
    saved.assign((size_t) size, 0.0);
    for (long k = 0; k < size; k++) saved[k] = sbc_saved_real(&rd, "pair state value");
    if (rd.st != SBC_OK) fail(err.message);
    if ((long) rd.at != total - 2)
      fail("restart: the block holds " + std::to_string(total) + " values, its contents " + std::to_string(rd.at + 2));
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
  const long count = sbc_saved_int(&rd, "sphere count", 1, (total - 2) / 6);
  const long nb = sbc_saved_int(&rd, "bond count", 0, total);
  const long per = sbc_saved_int(&rd, "doubles per bond", 1, 256);
  if (rd.st != SBC_OK) fail(err.message);
  if (15 + 6 * count + nb * per + 2 != total)
    fail("restart: the block holds " + std::to_string(total) + " values; " + std::to_string(count) + " spheres and " +
         std::to_string(nb) + " bonds of " + std::to_string(per) + " values need " +
         std::to_string(14 + 6 * count + nb * per + 2));
  n = (int) count;
  tags.assign(n, 0);
  ref_x.assign(3 * n, 0.0);
  ref_r.assign(n, 0.0);
  ref_m.assign(n, 0.0);
  for (int k = 0; k < n; k++) {
    tags[k] = (tagint) sbc_saved_int(&rd, "atom ID", 1, MAXTAGINT);
    for (int c = 0; c < 3; c++) ref_x[3 * k + c] = sbc_saved_real(&rd, "reference centre");
    ref_r[k] = sbc_saved_positive(&rd, "radius");
    ref_m[k] = sbc_saved_positive(&rd, "mass");
  }
  saved.assign((size_t) (nb * per), 0.0);
  for (long k = 0; k < nb * per; k++) saved[k] = sbc_saved_real(&rd, "bond state value");
  external_work = sbc_saved_real(&rd, "external work");
  fracture_saved = sbc_saved_real(&rd, "fracture energy");
  if (rd.st != SBC_OK) fail(err.message);
  if (!(fracture_saved >= 0.0)) fail("restart: the fracture energy " + std::to_string(fracture_saved) + " J < 0");
}

/* the group's atoms in ID order on every rank; the core bonds those that touch */
void FixServoBCBonds::create_bonds()
{
  const int nlocal = atom->nlocal;
  std::vector<double> pack;    // per atom: tag, x, y, z, radius, mass
  for (int i = 0; i < nlocal; i++)
    if (atom->mask[i] & groupbit)
      pack.insert(pack.end(), {(double) atom->tag[i], atom->x[i][0], atom->x[i][1], atom->x[i][2], atom->radius[i],
                               atom->rmass[i]});
  int count = (int) pack.size(), nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> every(displs[nprocs - 1] + counts[nprocs - 1]);
  MPI_Allgatherv(pack.data(), count, MPI_DOUBLE, every.data(), counts.data(), displs.data(), MPI_DOUBLE, world);
  n = (int) every.size() / 6;
  std::vector<int> order(n);
  for (int k = 0; k < n; k++) order[k] = k;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return every[6 * a] < every[6 * b]; });
  ref_x.assign(3 * n, 0.0);
  ref_r.assign(n, 0.0);
  ref_m.assign(n, 0.0);
  tags.assign(n, 0);
  for (int k = 0; k < n; k++) {
    const double *p = &every[6 * order[k]];
    tags[k] = (tagint) p[0];
    for (int c = 0; c < 3; c++) ref_x[3 * k + c] = p[1 + c];
    ref_r[k] = p[4];
    ref_m[k] = p[5];
  }
  if (contacts || model == "cohesive") bond_discs();
  else bond_spheres();
}

/* cohesive: the core's contacts on the group's discs at their present
   centres; from a restart file, its pair state replaces the new bonds */
void FixServoBCBonds::bond_discs()
{
  index.clear();
  for (int k = 0; k < n; k++) index[tags[k]] = k;
  std::vector<double> xy(2 * n);
  for (int k = 0; k < n; k++) {
    xy[2 * k] = ref_x[3 * k];
    xy[2 * k + 1] = ref_x[3 * k + 1];
  }
  char msg[512] = "";
  contacts = sbc_cohesive_host_create(words.c_str(), n, xy.data(), ref_r.data(), msg, sizeof msg);
  if (!contacts) fail(std::string(msg) + " (group " + group->names[igroup] + ")");
  if (!saved.empty()) {
    if (saved_tags != tags)
      fail("restart: the group's atoms (" + std::to_string(n) + ") are not the " + std::to_string(saved_tags.size()) +
           " atoms of the restart file's pair state");
    if (sbc_cohesive_host_state_set(contacts, saved.data(), saved.size()))
      fail(std::string("restart: ") + sbc_cohesive_host_message(contacts));
    saved.clear();
  }
  mine.assign(5 * n, 0.0);
  all.assign(5 * n, 0.0);
  load.assign(3 * n, 0.0);
  char line[256];
  std::snprintf(line, sizeof line, "fix servo_bc/bonds: %d cohesive bonds (%d formed) between %d discs\n",
                sbc_cohesive_host_bond_count(contacts), sbc_cohesive_host_bonds_initial(contacts), n);
  say(line);
}

/* the core's bonds on the reference spheres (at the first run, or those of a
   restart file, whose bond states are then put back) */
void FixServoBCBonds::bond_spheres()
{
  index.clear();
  for (int k = 0; k < n; k++) index[tags[k]] = k;
  char msg[512] = "";
  bonds = sbc_bpm_host_create(model.c_str(), E, nu, alpha, failure ? strength : nullptr, n, ref_x.data(), ref_r.data(), ref_m.data(), msg,
                              sizeof msg);
  if (!bonds) fail(std::string(msg) + " (group " + group->names[igroup] + ")");
  if (!saved.empty()) {
    const int nb = sbc_bpm_host_bond_count(bonds), per = sbc_bpm_host_state_doubles(bonds);
    if ((int) saved.size() != nb * per)
      fail("restart: the saved bonds (" + std::to_string(saved.size()) + " values) are not the " +
           std::to_string(nb) + " bonds these spheres form");
    for (int k = 0; k < nb; k++) sbc_bpm_host_state_set(bonds, k, &saved[(size_t) k * per]);
    sbc_bpm_host_set_fracture_energy(bonds, fracture_saved);
    saved.clear();
  }
  mine.assign(9 * n, 0.0);
  all.assign(9 * n, 0.0);
  load.assign(6 * n, 0.0);
  other.assign(6 * n, 0.0);
  other_prev.assign(6 * n, 0.0);
  other_mine.assign(6 * n, 0.0);
  char line[256];
  std::snprintf(line, sizeof line, "fix servo_bc/bonds: %d %s bonds between %d spheres, critical time step %.6g s\n",
                sbc_bpm_host_bond_count(bonds), model.c_str(), n, sbc_bpm_critical_dt(bonds));
  say(line);
}

/* x, v, omega of the group in ID order as three blocks, x | v | omega (3n
   each; cohesive: 2n | 2n | n, the plane's components and the spin about z),
   summed over ranks (each atom is owned once) */
void FixServoBCBonds::gather()
{
  std::fill(mine.begin(), mine.end(), 0.0);
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  const int spins = dim == 3 ? 3 : 1, first_spin = dim == 3 ? 0 : 2;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    auto it = index.find(atom->tag[i]);
    if (it == index.end()) fail("atom " + std::to_string((long) atom->tag[i]) + " joined the group after set-up");
    const int k = it->second;
    for (int c = 0; c < dim; c++) {
      mine[dim * k + c] = x[i][c];
      mine[dim * (n + k) + c] = v[i][c];
    }
    for (int c = 0; c < spins; c++) mine[2 * dim * n + spins * k + c] = omega[i][first_spin + c];
  }
  MPI_Allreduce(mine.data(), all.data(), (int) mine.size(), MPI_DOUBLE, MPI_SUM, world);
}

void FixServoBCBonds::setup(int) { post_force(0); }

/* the bonds' loads: the motion of the step just taken is dt v(t + dt/2)
   (velocity Verlet: v is at the half step here); the setup of a run sees the
   last configuration again, whose loads are added once more, unchanged */
void FixServoBCBonds::post_force(int)
{
  if (update->ntimestep != last_step) {
    gather();
    // the first evaluation (no step taken yet) builds no increment
    if (last_step < 0) std::fill(all.begin() + dim * n, all.end(), 0.0);
    const double *x = &all[0], *v = &all[dim * n], *w = &all[2 * dim * n];
    if (contacts) {
      if (sbc_cohesive_host_loads(contacts, x, v, w, update->dt, load.data()))
        fail("step " + std::to_string((long) update->ntimestep) + ": " + sbc_cohesive_host_message(contacts));
    } else if (sbc_bpm_host_loads(bonds, x, v, w, update->dt, load.data()))
      fail("a bond load is not finite at step " + std::to_string((long) update->ntimestep) + " (time step " +
           std::to_string(update->dt) + " s, eq. 48's critical step " + std::to_string(sbc_bpm_critical_dt(bonds)) +
           " s)");
    last_step = update->ntimestep;
  }
  double **f = atom->f, **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int k = index[atom->tag[i]];
    if (contacts) {
      const double *l = &load[3 * k];
      f[i][0] += l[0];
      f[i][1] += l[1];
      torque[i][2] += l[2];
      continue;
    }
    const double *l = &load[6 * k];
    for (int c = 0; c < 3; c++) {
      f[i][c] += l[c];
      torque[i][c] += l[3 + c];
    }
  }
}

void FixServoBCBonds::contact_sums(double out[4]) const
{
  if (contacts) sbc_cohesive_host_sums(contacts, out);
  else std::fill(out, out + 4, 0.0);
}

double FixServoBCBonds::compute_scalar()
{
  if (contacts) {
    double sums[4];
    sbc_cohesive_host_sums(contacts, sums);
    return sums[0];
  }
  return bonds ? sbc_bpm_host_strain_energy(bonds) : 0.0;
}

double FixServoBCBonds::compute_vector(int k)
{
  if (contacts) return k == 0 ? sbc_cohesive_host_bond_count(contacts) : sbc_cohesive_host_bonds_initial(contacts);
  if (!bonds) return 0.0;
  switch (k) {
    case 0: return sbc_bpm_host_intact(bonds);
    case 1: return sbc_bpm_critical_dt(bonds);
    case 2: return kinetic;
    case 3: return sbc_bpm_host_dissipated(bonds);
    case 4: return external_work;
    default: {    // eq. 53
      const double u = sbc_bpm_host_strain_energy(bonds), d = sbc_bpm_host_dissipated(bonds);
      double big = std::max(std::fabs(kinetic), std::max(std::fabs(u), std::fabs(external_work)));
      big = std::max(big, std::fabs(d));
      return big > 0.0 ? std::fabs(kinetic + u + d - external_work) / big : 0.0;
    }
  }
}

void FixServoBCBonds::end_of_step()
{
  if (bonds) energy_step();
}

/* eqs. 49 and 52 after the step: every force and moment on the group is in
   f and torque now (other fixes add theirs after this fix's post_force); the
   others' share is that less the bonds' loads. The motion of the step is
   dt v(t - dt/2 .. t + dt/2) as gathered in post_force, so the work of the
   step is (F(t) + F(t + dt)) / 2 . dt v (and likewise for the moments). */
void FixServoBCBonds::energy_step()
{
  std::fill(other_mine.begin(), other_mine.end(), 0.0);
  double **f = atom->f, **torque = atom->torque, **v = atom->v, **omega = atom->omega;
  double ek = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int k = index[atom->tag[i]];
    const double m = atom->rmass[i], I = 0.4 * m * atom->radius[i] * atom->radius[i];
    for (int c = 0; c < 3; c++) {
      other_mine[6 * k + c] = f[i][c] - load[6 * k + c];
      other_mine[6 * k + 3 + c] = torque[i][c] - load[6 * k + 3 + c];
      ek += 0.5 * m * v[i][c] * v[i][c] + 0.5 * I * omega[i][c] * omega[i][c];
    }
  }
  MPI_Allreduce(other_mine.data(), other.data(), 6 * n, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&ek, &kinetic, 1, MPI_DOUBLE, MPI_SUM, world);
  if (!have_prev) other_prev = other;    // the first step: the loads of its end on both sides
  const double dt = update->dt;
  double w = 0.0;
  for (int k = 0; k < n; k++)
    for (int c = 0; c < 3; c++) {
      w += 0.5 * (other_prev[6 * k + c] + other[6 * k + c]) * dt * all[3 * (n + k) + c];
      w += 0.5 * (other_prev[6 * k + 3 + c] + other[6 * k + 3 + c]) * dt * all[3 * (2 * n + k) + c];
    }
  external_work += w;
  other_prev.swap(other);
  have_prev = true;
}
