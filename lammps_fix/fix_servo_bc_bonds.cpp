/* ----------------------------------------------------------------------
   fix servo_bc/bonds (see fix_servo_bc_bonds.h):
     fix ID group servo_bc/bonds MODEL E nu alpha
   MODEL = beam (Timoshenko beams, E_b = E Pa, nu_b = nu) or parallel
   (parallel bonds, k^n = E / 2 r_min, k^s = k^n / 4.2); bond radius
   alpha r_min. Bonds join the group's spheres that touch at the first run.
   Outputs: f_ID (scalar) the bonds' strain energy (J); f_ID[1] the bond
   count, f_ID[2] eq. 48's critical time step (s).
------------------------------------------------------------------------- */

#include "fix_servo_bc_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "update.h"

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

FixServoBCBonds::FixServoBCBonds(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), E(0.0), nu(0.0), alpha(0.0), bonds(nullptr), n(0), last_step(-1)
{
  if (narg != 7)
    fail(std::string("expected 4 arguments after the style (MODEL E nu alpha), got ") + std::to_string(narg - 3));
  model = arg[3];
  if (model != "beam" && model != "parallel")
    fail("model '" + model + "' is not valid (expected beam or parallel)");
  const char *names[3] = {"E", "nu", "alpha"};
  double *values[3] = {&E, &nu, &alpha};
  for (int k = 0; k < 3; k++) {
    char *end = nullptr;
    *values[k] = std::strtod(arg[4 + k], &end);
    if (end == arg[4 + k] || *end != '\0' || !std::isfinite(*values[k]))
      fail(std::string("keyword ") + names[k] + ": '" + arg[4 + k] + "' is not a number");
  }
  if (!(E > 0.0) || !(nu > -1.0 && nu < 0.5) || !(alpha > 0.0))
    fail("E " + std::string(arg[4]) + ", nu " + arg[5] + ", alpha " + arg[6] +
         " (expected E > 0 Pa, -1 < nu < 0.5, alpha > 0)");
  if (!atom->sphere_flag) fail("requires atom_style sphere");
  if (std::strcmp(update->unit_style, "si") != 0)
    fail(std::string("requires units si (E in Pa; this script has units ") + update->unit_style + ")");
  if (domain->dimension != 3) fail("requires a 3d box (the bond models are 3D)");
  restart_global = 1;
  scalar_flag = 1;
  vector_flag = 1;
  size_vector = 2;
  global_freq = 1;
  extscalar = 0;
  extvector = 0;
}

FixServoBCBonds::~FixServoBCBonds() { sbc_bpm_destroy(bonds); }

int FixServoBCBonds::setmask() { return POST_FORCE; }

void FixServoBCBonds::fail(const std::string &message)
{
  last_error = "Fix servo_bc/bonds: " + message;    // kept: LIGGGHTS' error->all takes a C string
  error->all(FLERR, last_error.c_str());
}

void FixServoBCBonds::init()
{
  if (bonds) return;
  if (tags.empty()) create_bonds();
  else bond_spheres();    // from a restart file
}

namespace {
// marks fix servo_bc/bonds' restart block (bump on any change of its layout)
const double BONDS_MAGIC = 8.020002e7;
}

/* rank 0: model, E, nu, alpha, the reference spheres (ID, centre, radius,
   mass) and every bond's state */
void FixServoBCBonds::write_restart(FILE *fp)
{
  if (comm->me != 0 || !bonds) return;
  const int nb = sbc_bpm_host_bond_count(bonds), per = sbc_bpm_host_state_doubles(bonds);
  std::vector<double> list = {BONDS_MAGIC, model == "beam" ? 1.0 : 2.0, E, nu, alpha, (double) n, (double) nb,
                              (double) per};
  for (int k = 0; k < n; k++)
    list.insert(list.end(), {(double) tags[k], ref_x[3 * k], ref_x[3 * k + 1], ref_x[3 * k + 2], ref_r[k], ref_m[k]});
  std::vector<double> state(per);
  for (int k = 0; k < nb; k++) {
    sbc_bpm_host_state_get(bonds, k, state.data());
    list.insert(list.end(), state.begin(), state.end());
  }
  int size = (int) (list.size() * sizeof(double));
  fwrite(&size, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

void FixServoBCBonds::restart(char *raw)
{
  const double *list = (const double *) raw;
  if (list[0] != BONDS_MAGIC) fail("restart: this fix's block in the restart file is not fix servo_bc/bonds'");
  const std::string saved_model = list[1] == 1.0 ? "beam" : "parallel";
  if (saved_model != model || list[2] != E || list[3] != nu || list[4] != alpha)
    fail("restart: the file's bonds are " + saved_model + " " + std::to_string(list[2]) + " " +
         std::to_string(list[3]) + " " + std::to_string(list[4]) + "; this fix asks for other ones");
  n = (int) list[5];
  const int nb = (int) list[6], per = (int) list[7];
  const double *p = &list[8];
  tags.assign(n, 0);
  ref_x.assign(3 * n, 0.0);
  ref_r.assign(n, 0.0);
  ref_m.assign(n, 0.0);
  for (int k = 0; k < n; k++, p += 6) {
    tags[k] = (tagint) p[0];
    for (int c = 0; c < 3; c++) ref_x[3 * k + c] = p[1 + c];
    ref_r[k] = p[4];
    ref_m[k] = p[5];
  }
  saved.assign(p, p + (size_t) nb * per);
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
  bond_spheres();
}

/* the core's bonds on the reference spheres (at the first run, or those of a
   restart file, whose bond states are then put back) */
void FixServoBCBonds::bond_spheres()
{
  index.clear();
  for (int k = 0; k < n; k++) index[tags[k]] = k;
  char msg[512] = "";
  bonds = sbc_bpm_host_create(model.c_str(), E, nu, alpha, n, ref_x.data(), ref_r.data(), ref_m.data(), msg,
                              sizeof msg);
  if (!bonds) fail(std::string(msg) + " (group " + group->names[igroup] + ")");
  if (!saved.empty()) {
    const int nb = sbc_bpm_host_bond_count(bonds), per = sbc_bpm_host_state_doubles(bonds);
    if ((int) saved.size() != nb * per)
      fail("restart: the saved bonds (" + std::to_string(saved.size()) + " values) are not the " +
           std::to_string(nb) + " bonds these spheres form");
    for (int k = 0; k < nb; k++) sbc_bpm_host_state_set(bonds, k, &saved[(size_t) k * per]);
    saved.clear();
  }
  mine.assign(9 * n, 0.0);
  all.assign(9 * n, 0.0);
  load.assign(6 * n, 0.0);
  if (comm->me == 0) {
    char line[256];
    std::snprintf(line, sizeof line, "fix servo_bc/bonds: %d %s bonds between %d spheres, critical time step %.6g s\n",
                  sbc_bpm_host_bond_count(bonds), model.c_str(), n, sbc_bpm_critical_dt(bonds));
    if (screen) fputs(line, screen);
    if (logfile) fputs(line, logfile);
  }
}

/* x, v, omega of the group in ID order, as three blocks of 3n (x | v | omega),
   summed over ranks (each atom is owned once) */
void FixServoBCBonds::gather()
{
  std::fill(mine.begin(), mine.end(), 0.0);
  double **x = atom->x, **v = atom->v, **omega = atom->omega;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    auto it = index.find(atom->tag[i]);
    if (it == index.end()) fail("atom " + std::to_string((long) atom->tag[i]) + " joined the group after set-up");
    const int k = it->second;
    for (int c = 0; c < 3; c++) {
      mine[3 * k + c] = x[i][c];
      mine[3 * (n + k) + c] = v[i][c];
      mine[3 * (2 * n + k) + c] = omega[i][c];
    }
  }
  MPI_Allreduce(mine.data(), all.data(), 9 * n, MPI_DOUBLE, MPI_SUM, world);
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
    if (last_step < 0) std::fill(all.begin() + 3 * n, all.end(), 0.0);
    if (sbc_bpm_host_loads(bonds, &all[0], &all[3 * n], &all[6 * n], update->dt, load.data()))
      fail("a bond load is not finite at step " + std::to_string((long) update->ntimestep) + " (time step " +
           std::to_string(update->dt) + " s, eq. 48's critical step " + std::to_string(sbc_bpm_critical_dt(bonds)) +
           " s)");
    last_step = update->ntimestep;
  }
  double **f = atom->f, **torque = atom->torque;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *l = &load[6 * index[atom->tag[i]]];
    for (int c = 0; c < 3; c++) {
      f[i][c] += l[c];
      torque[i][c] += l[3 + c];
    }
  }
}

double FixServoBCBonds::compute_scalar() { return bonds ? sbc_bpm_host_strain_energy(bonds) : 0.0; }

double FixServoBCBonds::compute_vector(int k)
{
  if (!bonds) return 0.0;
  return k == 0 ? sbc_bpm_host_bond_count(bonds) : sbc_bpm_critical_dt(bonds);
}
