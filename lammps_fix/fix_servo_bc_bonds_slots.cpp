/* ----------------------------------------------------------------------
   fix servo_bc/bonds: the per-atom slots (also cohesive's, whose pairs are
   in fix_servo_bc_bonds_contacts.cpp) and beam | parallel: each bond kept with its atoms
   (fix_servo_bc_bonds.h). Per atom, slot[i] = [count, (partner ID, state)
   x count], partners in ascending ID; both atoms of a bond hold a copy of
   its state and advance it alike (end A is the smaller ID), so the two
   owners agree on every load and on the step a bond breaks. The slots
   migrate with their atoms (pack_exchange) and go into restart files
   (pack_restart); the partner of each slot is looked up once per neighbour
   build (map_images) and must then be owned or a ghost of this rank, unless
   the bond is broken (its contact is then apart).
------------------------------------------------------------------------- */

#include "fix_servo_bc_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
// per-atom values beside the slots: the other loads of the last end of step
// (6), the external work of eq. 52 on the atom (J), the fracture energy of the
// bonds it is end A of (J)
constexpr int CARRY = 8, WORK = 6, FRACTURE = 7;
// partner_slot of a slot whose partner, owned here too, is end A
constexpr int SKIP = -2;
}    // namespace

/* the group's size over every rank: n, r_min (kept) and r_max (m), m_min (kg);
   a radius or mass that is not positive stops the run naming the atom */
void FixServoBCBonds::survey_group(double &rmax, double &mmin)
{
  double lo[3] = {1e300, 0.0, 1e300}, hi[3];
  int count = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double r = atom->radius[i], m = atom->rmass[i];
    if (!(r > 0.0) || !std::isfinite(r) || !(m > 0.0))
      fail_here("atom " + std::to_string((long) atom->tag[i]) + ": radius " + std::to_string(r) + " m, mass " +
                std::to_string(m) + " kg (expected > 0)");
    lo[0] = std::min(lo[0], r);    // r_min
    lo[1] = std::max(lo[1], r);    // r_max (negated below)
    lo[2] = std::min(lo[2], m);    // m_min
    count++;
  }
  lo[1] = -lo[1];
  MPI_Allreduce(lo, hi, 3, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(&count, &n, 1, MPI_INT, MPI_SUM, world);
  if (n < 2) fail("group " + std::string(group->names[igroup]) + " has " + std::to_string(n) + " atoms (bonds need 2)");
  rmin = hi[0];
  rmax = -hi[1];
  mmin = hi[2];
}

/* the group's touching spheres, owned and ghost, bonded at the first run */
void FixServoBCBonds::create_slots()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **x = atom->x, *radius = atom->radius;
  int *mask = atom->mask;
  tagint *tag = atom->tag;
  double rmax, mmin;
  survey_group(rmax, mmin);
  char msg[512] = "";
  bonds = sbc_bpm_host_law(model.c_str(), E, nu, alpha, failure ? strength : nullptr, rmin, msg, sizeof msg);
  if (!bonds) fail(std::string(msg) + " (group " + group->names[igroup] + ")");
  per = sbc_bpm_host_state_doubles(bonds);
  // a bond forms at |xb - xa| <= (ra + rb)(1 + touch): the partner must be a ghost when another rank owns it
  const double reach = 2.0 * rmax * (1.0 + bonds->set.touch);
  const double cut = std::min(comm->cutghost[0], std::min(comm->cutghost[1], comm->cutghost[2]));
  if ((comm->nprocs > 1 || domain->xperiodic || domain->yperiodic || domain->zperiodic) && cut < reach)
    fail("the ghost cutoff " + std::to_string(cut) + " m is shorter than a bond at creation (2 r_max = " +
         std::to_string(reach) + " m); set it to the longest a bond may stretch to (comm_modify cutoff in "
         "LAMMPS, communicate single cutoff in LIGGGHTS)");

  // touching pairs among owned and ghost spheres of the group (the core's grid)
  std::vector<int> at;
  std::vector<double> xs, rs;
  for (int i = 0; i < nall; i++)
    if (mask[i] & groupbit) {
      at.push_back(i);
      xs.insert(xs.end(), {x[i][0], x[i][1], x[i][2]});
      rs.push_back(radius[i]);
    }
  int *pairs = nullptr;
  const long np = sbc_bpm_host_pairs(bonds, (int) at.size(), xs.data(), rs.data(), &pairs, msg, sizeof msg);
  if (np < 0) fail_here(msg);
  struct Entry {
    int i;
    tagint partner;
    int j;
  };
  std::vector<Entry> entries;
  for (long p = 0; p < np; p++) {
    const int a = at[pairs[2 * p]], b = at[pairs[2 * p + 1]];
    if (a < nlocal) entries.push_back({a, tag[b], b});
    if (b < nlocal) entries.push_back({b, tag[a], a});
  }
  sbc_bpm_host_pairs_free(pairs);
  std::sort(entries.begin(), entries.end(), [](const Entry &p, const Entry &q) {
    return p.i != q.i ? p.i < q.i : p.partner < q.partner;
  });
  // a periodic image of the same partner touching too (a box narrower than two spheres) bonds once
  entries.erase(std::unique(entries.begin(), entries.end(),
                            [](const Entry &p, const Entry &q) { return p.i == q.i && p.partner == q.partner; }),
                entries.end());
  int most = 0;
  for (size_t e = 0; e < entries.size();) {
    size_t f = e;
    while (f < entries.size() && entries[f].i == entries[e].i) f++;
    most = std::max(most, (int) (f - e));
    e = f;
  }
  MPI_Allreduce(&most, &maxb, 1, MPI_INT, MPI_MAX, world);
  if (maxb == 0) fail("no two spheres touch, so no bond formed (group " + std::string(group->names[igroup]) + ")");
  size_slots();
  double local[3] = {0.0, 0.0, 0.0};    // bonds formed here (end A owned), the longest, the stiffest
  for (const Entry &e : entries) {
    double *row = slot[e.i];
    const int s = (int) row[0]++;
    double *state = &row[2 + s * (1 + per)];
    row[1 + s * (1 + per)] = (double) e.partner;
    const bool a_here = tag[e.i] < e.partner;
    const int a = a_here ? e.i : e.j, b = a_here ? e.j : e.i;
    sbc_bpm_host_bond_start(bonds, x[a], radius[a], x[b], radius[b], state);
    const double d[3] = {x[b][0] - x[a][0], x[b][1] - x[a][1], x[b][2] - x[a][2]};
    local[0] += a_here;
    local[1] = std::max(local[1], std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]));
    local[2] = std::max(local[2], sbc_bpm_host_bond_stiffness(bonds, state));
  }
  double total = 0.0, most2[2];
  MPI_Allreduce(&local[0], &total, 1, MPI_DOUBLE, MPI_SUM, world);
  MPI_Allreduce(&local[1], most2, 2, MPI_DOUBLE, MPI_MAX, world);
  formed = (int) total;
  longest = most2[0];
  critical_dt = sbc_bpm_critical_dt_of(mmin, most2[1]);
  char line[256];
  std::snprintf(line, sizeof line,
                "fix servo_bc/bonds: %d %s bonds between %d spheres, critical time step %.6g s, longest %.6g m\n",
                formed, model.c_str(), n, critical_dt, longest);
  say(line);
}

/* the slots' width from maxb and per, the exchange's room for it, the rows */
void FixServoBCBonds::size_slots()
{
  width = 1 + maxb * (1 + per);
#ifndef SERVO_BC_LIGGGHTS
  maxexchange = CARRY + width;
#else
  if (CARRY + width > 1000)    // LIGGGHTS 3.8's exchange buffer keeps 1000 values per atom spare
    fail(std::to_string(maxb) + " bonds on one sphere need " + std::to_string(CARRY + width) +
         " values per atom in an exchange; LIGGGHTS 3.8 moves at most 1000");
#endif
  grow_arrays(atom->nmax);
}

/* atom ID -> its owned and ghost indices among the group (partner), once
   per neighbour build */
void FixServoBCBonds::map_images()
{
  const int nall = atom->nlocal + atom->nghost;
  tagint *tag = atom->tag;
  image_first.clear();
  image_next.assign(nall, -1);
  for (int i = 0; i < nall; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    auto in = image_first.emplace(tag[i], i);
    if (!in.second) {
      image_next[i] = in.first->second;
      in.first->second = i;
    }
  }
}

/* the partner of every slot of the owned atoms: an owned or ghost index, the
   image closest to the atom (periodic boxes), once per neighbour build */
void FixServoBCBonds::map_partners()
{
  if (comm->me == 0 && !breaks_file.empty() && !breaks_fp) {
    breaks_fp = std::fopen(breaks_file.c_str(), restarted ? "a" : "w");
    if (!breaks_fp) fail_here("keyword breaks: cannot open '" + breaks_file + "' for writing");
    if (!restarted) std::fputs("step,id_a,id_b,x,y,z\n", breaks_fp);
  }
  const int nlocal = atom->nlocal;
  double **x = atom->x;
  tagint *tag = atom->tag;
  map_images();
  for (int i = 0; i < nlocal; i++) {
    const int count = (int) slot[i][0];
    for (int s = 0; s < count; s++) {
      const tagint t = (tagint) slot[i][1 + s * (1 + per)];
      const int j = partner(t, x[i]);
      // a broken bond's partner out of reach: its contact is apart (step_slots)
      if (j < 0 && sbc_bpm_host_bond_broken(bonds, &slot[i][2 + s * (1 + per)])) {
        partner_at[i][s] = -1;
        continue;
      }
      if (j < 0) {
        const double cut = std::min(comm->cutghost[0], std::min(comm->cutghost[1], comm->cutghost[2]));
        fail_here("the bond of atoms " + std::to_string((long) tag[i]) + " and " + std::to_string((long) t) +
                  ": atom " + std::to_string((long) t) + " is neither owned by rank " + std::to_string(comm->me) +
                  " nor one of its ghosts (ghost cutoff " + std::to_string(cut) +
                  " m; the longest bond at creation " + std::to_string(longest) +
                  " m): the bond stretched past the cutoff; raise it (comm_modify cutoff in LAMMPS, "
                  "communicate single cutoff in LIGGGHTS)");
      }
      partner_at[i][s] = j;
    }
  }
  // the same bond in the partner's slots, when this rank owns both atoms (SKIP: the partner is end A)
  slot_count.resize(nlocal);
  for (int i = 0; i < nlocal; i++) {
    const int count = slot_count[i] = (int) slot[i][0];
    for (int s = 0; s < count; s++) {
      const int j = partner_at[i][s];
      partner_slot[i][s] = -1;
      if (j < 0 || j >= nlocal) continue;
      if (tag[j] < tag[i]) {
        partner_slot[i][s] = SKIP;
        continue;
      }
      const int other = (int) slot[j][0];
      for (int q = 0; q < other && partner_slot[i][s] < 0; q++)
        if ((tagint) slot[j][1 + q * (1 + per)] == tag[i]) partner_slot[i][s] = q;
      if (partner_slot[i][s] < 0)
        fail_here("atom " + std::to_string((long) tag[j]) + " keeps no bond to atom " + std::to_string((long) tag[i]) +
                  ", which keeps one to it (its per-atom data were changed)");
    }
  }
}

int FixServoBCBonds::partner(tagint t, const double *near) const
{
  auto it = image_first.find(t);
  if (it == image_first.end()) return -1;
  double **x = atom->x, best = 0.0;
  int closest = -1;
  for (int j = it->second; j >= 0; j = image_next[j]) {
    const double d[3] = {x[j][0] - near[0], x[j][1] - near[1], x[j][2] - near[2]};
    const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    if (closest < 0 || dd < best) {
      best = dd;
      closest = j;
    }
  }
  return closest;
}

/* every bond of the owned atoms: their loads into f and torque; motion false
   (a run's setup) sees the last configuration again with no motion, so the
   states keep their loads and the same loads are added. A bond whose atoms
   this rank both owns is advanced once, in end A's slot; end B's copy is
   brought up to date before it can leave or be written (sync_copies). A
   bond to a ghost is advanced here and on the ghost's rank alike. Each atom then sums its bonds' loads in slot order, so the
   sums do not depend on which partners are ghosts, nor the results on the
   rank count */
void FixServoBCBonds::step_slots(bool motion)
{
  if (motion && !comm->ghost_velocity) comm->forward_comm_fix(this);    // v, omega of the ghosts
  const int nlocal = atom->nlocal;
  double **x = atom->x, **v = atom->v, **omega = atom->omega, **f = atom->f, **torque = atom->torque;
  double *radius = atom->radius;
  tagint *tag = atom->tag;
  const double dt = update->dt, rest[3] = {0.0, 0.0, 0.0};
  const int stride = 1 + per;
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double *vi = motion ? v[i] : rest, *wi = motion ? omega[i] : rest;
    for (int c = 0; c < 3; c++) {
      step_motion[i][c] = vi[c];
      step_motion[i][3 + c] = wi[c];
    }
    const int count = slot_count[i];
    for (int s = 0; s < count; s++) {
      const int j = partner_at[i][s];
      if (partner_slot[i][s] == SKIP) continue;    // advanced from its end A, the partner (its row untouched)
      double *state = &slot[i][2 + s * stride], *own = &slot_load[i][6 * s];
      if (j < 0) {
        sbc_bpm_host_bond_apart(bonds, state);
        for (int c = 0; c < 6; c++) own[c] = 0.0;
        continue;
      }
      const tagint t = tag[j];
      const double *vj = motion ? v[j] : rest, *wj = motion ? omega[j] : rest;
      double la[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, lb[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0}, w = 0.0;
      const bool a_here = tag[i] < t;
      const int a = a_here ? i : j, b = a_here ? j : i;
      const double *va = a_here ? vi : vj, *wa = a_here ? wi : wj, *vb = a_here ? vj : vi, *wb = a_here ? wj : wi;
      if (sbc_bpm_host_bond_step(bonds, state, x[a], radius[a], va, wa, x[b], radius[b], vb, wb, dt, la, lb, &w) &&
          a_here) {
        carry[i][FRACTURE] += w;
        break_rows.insert(break_rows.end(), {(double) update->ntimestep, (double) tag[i], (double) t,
                                             0.5 * (x[i][0] + x[j][0]), 0.5 * (x[i][1] + x[j][1]),
                                             0.5 * (x[i][2] + x[j][2])});
      }
      for (int c = 0; c < 6; c++) own[c] = a_here ? la[c] : lb[c];
      if (j < nlocal) {    // end B is owned here too: its load (its copy of the state waits: sync_copies)
        const int q = partner_slot[i][s];
        for (int c = 0; c < 6; c++) slot_load[j][6 * q + c] = lb[c];
        copies_stale = true;
      }
    }
  }
  for (int i = 0; i < nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    double acc[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const int count = slot_count[i];
    for (int s = 0; s < count; s++)
      for (int c = 0; c < 6; c++) acc[c] += slot_load[i][6 * s + c];
    for (int c = 0; c < 6; c++)
      if (!std::isfinite(acc[c]))
        fail_here("a bond load on atom " + std::to_string((long) tag[i]) + " is not finite at step " +
                  std::to_string((long) update->ntimestep) + " (time step " + std::to_string(dt) +
                  " s, eq. 48's critical step " + std::to_string(critical_dt) + " s)");
    for (int c = 0; c < 3; c++) {
      f[i][c] += acc[c];
      torque[i][c] += acc[3 + c];
      step_load[i][c] = acc[c];
      step_load[i][3 + c] = acc[3 + c];
    }
  }
  reduced_at = -1;
}

/* end B's copy of every bond whose atoms this rank owns, from end A's: before
   atoms migrate (pre_exchange; a run's end, after which any command may move
   them) and before restart data are written. The partners' indices are those
   of the last neighbour build, still valid at these points */
void FixServoBCBonds::sync_copies()
{
  if (!copies_stale) return;
  const int nlocal = atom->nlocal, stride = 1 + per;
  for (int i = 0; i < nlocal; i++) {
    const int count = (int) slot[i][0];
    for (int s = 0; s < count; s++) {
      const int j = partner_at[i][s];
      if (j < 0 || j >= nlocal || partner_slot[i][s] < 0) continue;
      std::memcpy(&slot[j][2 + partner_slot[i][s] * stride], &slot[i][2 + s * stride], sizeof(double) * per);
    }
  }
  copies_stale = false;
}

/* eqs. 49 and 52 after the step: every force and moment on the group is in f
   and torque now (other fixes add theirs after this fix's post_force); the
   others' share is that less the bonds' loads. The motion of the step is
   dt v(t - dt/2 .. t + dt/2) as seen in post_force, so the work of the step
   is (F(t) + F(t + dt)) / 2 . dt v (and likewise for the moments), summed on
   each atom */
void FixServoBCBonds::energy_slots()
{
  double **f = atom->f, **torque = atom->torque, **v = atom->v, **omega = atom->omega;
  const double dt = update->dt;
  double ek = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const double m = atom->rmass[i], I = 0.4 * m * atom->radius[i] * atom->radius[i];
    double other[6], w = 0.0;
    for (int c = 0; c < 3; c++) {
      other[c] = f[i][c] - step_load[i][c];
      other[3 + c] = torque[i][c] - step_load[i][3 + c];
      ek += 0.5 * m * v[i][c] * v[i][c] + 0.5 * I * omega[i][c] * omega[i][c];
    }
    const double *prev = have_prev ? carry[i] : other;    // the first step: the loads of its end on both sides
    for (int c = 0; c < 6; c++) w += 0.5 * (prev[c] + other[c]) * dt * step_motion[i][c];
    carry[i][WORK] += w;
    for (int c = 0; c < 6; c++) carry[i][c] = other[c];
  }
  kinetic_mine = ek;
  have_prev = true;
  reduced_at = -1;
}

/* the outputs summed over ranks: each bond counted once, by the owner of its end A */
void FixServoBCBonds::reduce_outputs()
{
  if (reduced_at == update->ntimestep) return;
  if (dim == 2) {    // cohesive: eq. 12's Ep and the intact bonds of the pairs whose end A is owned
    const double mine[2] = {contact_mine[0], (double) intact_mine};
    MPI_Allreduce(mine, sums, 2, MPI_DOUBLE, MPI_SUM, world);
    reduced_at = update->ntimestep;
    return;
  }
  double mine[5] = {0.0, 0.0, kinetic_mine, 0.0, 0.0};
  double **x = atom->x, *radius = atom->radius;
  tagint *tag = atom->tag;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(atom->mask[i] & groupbit)) continue;
    const int count = (int) slot[i][0];
    for (int s = 0; s < count; s++) {
      if (tag[i] > (tagint) slot[i][1 + s * (1 + per)]) continue;
      const double *state = &slot[i][2 + s * (1 + per)];
      const int j = partner_at[i][s];
      double strain = 0.0, friction = 0.0;
      sbc_bpm_host_bond_energies(bonds, state, x[i], radius[i], j < 0 ? nullptr : x[j], j < 0 ? 0.0 : radius[j],
                                 &strain, &friction);
      mine[0] += strain;
      mine[1] += !sbc_bpm_host_bond_broken(bonds, state);
      mine[3] += friction;
    }
    mine[3] += carry[i][FRACTURE];
    mine[4] += carry[i][WORK];
  }
  MPI_Allreduce(mine, sums, 5, MPI_DOUBLE, MPI_SUM, world);
  reduced_at = update->ntimestep;
}

/* keyword breaks: this step's broken bonds from every rank, on rank 0, in ID order */
void FixServoBCBonds::write_breaks()
{
  int count = (int) break_rows.size(), nprocs = comm->nprocs;
  std::vector<int> counts(nprocs), displs(nprocs, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, world);
  for (int p = 1; p < nprocs; p++) displs[p] = displs[p - 1] + counts[p - 1];
  std::vector<double> rows(comm->me == 0 ? displs[nprocs - 1] + counts[nprocs - 1] : 0);
  MPI_Gatherv(break_rows.data(), count, MPI_DOUBLE, rows.data(), counts.data(), displs.data(), MPI_DOUBLE, 0, world);
  break_rows.clear();
  if (comm->me != 0 || rows.empty() || !breaks_fp) return;
  std::vector<int> order(rows.size() / 6);
  for (size_t k = 0; k < order.size(); k++) order[k] = (int) k;
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return rows[6 * a + 1] != rows[6 * b + 1] ? rows[6 * a + 1] < rows[6 * b + 1] : rows[6 * a + 2] < rows[6 * b + 2];
  });
  for (int k : order) {
    const double *r = &rows[6 * k];
    std::fprintf(breaks_fp, "%ld,%ld,%ld,%.17g,%.17g,%.17g\n", (long) r[0], (long) r[1], (long) r[2], r[3], r[4],
                 r[5]);
  }
  std::fflush(breaks_fp);
}

/* ---- per-atom data ---- */

void FixServoBCBonds::grow_arrays(int nmax)
{
  const bool fresh = width > 0 && !slot;
  if (width > 0) memory->grow(slot, nmax, width, "servo_bc/bonds:slot");
  if (width > 0 && dim == 3) {
    memory->grow(partner_at, nmax, maxb, "servo_bc/bonds:partner_at");
    memory->grow(partner_slot, nmax, maxb, "servo_bc/bonds:partner_slot");
    memory->grow(slot_load, nmax, 6 * maxb, "servo_bc/bonds:slot_load");
  }
  memory->grow(carry, nmax, CARRY, "servo_bc/bonds:carry");
  if (dim == 3) {    // beam | parallel: eqs. 49-52's per-step loads and motion
    memory->grow(step_load, nmax, 6, "servo_bc/bonds:step_load");
    memory->grow(step_motion, nmax, 6, "servo_bc/bonds:step_motion");
  }
  if (width > 0)
    for (int i = fresh ? 0 : nmax_slots; i < nmax; i++) slot[i][0] = 0.0;
  for (int i = nmax_slots; i < nmax; i++)
    for (int c = 0; c < CARRY; c++) carry[i][c] = 0.0;
  nmax_slots = nmax;
}

void FixServoBCBonds::copy_arrays(int i, int j, int)
{
  for (int c = 0; c < CARRY; c++) carry[j][c] = carry[i][c];
  if (width > 0) std::memcpy(slot[j], slot[i], sizeof(double) * (1 + (int) slot[i][0] * (1 + per)));
}

int FixServoBCBonds::pack_exchange(int i, double *out)
{
  for (int c = 0; c < CARRY; c++) out[c] = carry[i][c];
  if (width == 0) {
    out[CARRY] = 0.0;
    return CARRY + 1;
  }
  const int size = 1 + (int) slot[i][0] * (1 + per);
  std::memcpy(&out[CARRY], slot[i], sizeof(double) * size);
  return CARRY + size;
}

int FixServoBCBonds::unpack_exchange(int nlocal, double *in)
{
  for (int c = 0; c < CARRY; c++) carry[nlocal][c] = in[c];
  const int size = 1 + (int) in[CARRY] * (1 + per);
  if (width > 0) std::memcpy(slot[nlocal], &in[CARRY], sizeof(double) * size);
  return CARRY + size;
}

/* restart: size, the external work and fracture energy on the atom (J), the
   slot count, then per slot the partner's ID and the bond's state */
int FixServoBCBonds::pack_restart(int i, double *out)
{
  const int count = width > 0 ? (int) slot[i][0] : 0, size = 4 + count * (1 + per);
  out[0] = size;
  out[1] = carry[i][WORK];
  out[2] = carry[i][FRACTURE];
  out[3] = count;
  if (count) std::memcpy(&out[4], &slot[i][1], sizeof(double) * count * (1 + per));
  return size;
}

/* every value checked (sbc/saved.h) before it is used */
void FixServoBCBonds::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  if (width == 0) fail_here("restart: per-atom bond data without the fix's own block");
  const double *in = &extra[nlocal][m];
  sbc_error err;
  sbc_saved rd;
  const std::string who = "restart data of atom " + std::to_string((long) atom->tag[nlocal]);
  sbc_saved_start(&rd, in, 4, who.c_str(), &err);
  const long size = sbc_saved_int(&rd, "per-atom size", 4, 4L + (long) maxb * (1 + per));
  const double work = sbc_saved_real(&rd, "external work"), fracture = sbc_saved_real(&rd, "fracture energy");
  const long count = sbc_saved_int(&rd, "bond count", 0, maxb);
  if (rd.st != SBC_OK) fail_here(err.message);
  if (size != 4 + count * (1 + per))
    fail_here(who + ": " + std::to_string(size) + " values for " + std::to_string(count) + " bonds of " +
              std::to_string(per) + " values each");
  sbc_saved_start(&rd, in + 4, (size_t) (size - 4), who.c_str(), &err);
  for (long s = 0; s < count && rd.st == SBC_OK; s++) {
    slot[nlocal][1 + s * (1 + per)] = (double) sbc_saved_int(&rd, "partner ID", 1, MAXTAGINT);
    for (int q = 0; q < per; q++) slot[nlocal][2 + s * (1 + per) + q] = sbc_saved_real(&rd, "bond state value");
    if (dim == 2 && rd.st == SBC_OK && (slot[nlocal][2 + s * (1 + per)] != 0.0 && slot[nlocal][2 + s * (1 + per)] != 1.0))
      fail_here(who + ": pair " + std::to_string(s) + "'s intact flag " +
                std::to_string(slot[nlocal][2 + s * (1 + per)]) + " (expected 0 or 1)");
  }
  if (rd.st != SBC_OK) fail_here(err.message);
  if (!(fracture >= 0.0)) fail_here(who + ": the fracture energy " + std::to_string(fracture) + " J < 0");
  slot[nlocal][0] = (double) count;
  carry[nlocal][WORK] = work;
  carry[nlocal][FRACTURE] = fracture;
}

int FixServoBCBonds::size_restart(int i)
{
  return 4 + (width > 0 ? (int) slot[i][0] : 0) * (1 + per);
}

int FixServoBCBonds::maxsize_restart()
{
  return 4 + maxb * (1 + per);
}

/* the ghosts' velocity and spin for the bonds (when the host does not send them) */
#ifdef SERVO_BC_LIGGGHTS
int FixServoBCBonds::pack_comm(int count, int *list, double *buf, int, int *)
#else
int FixServoBCBonds::pack_forward_comm(int count, int *list, double *buf, int, int *)
#endif
{
  double **v = atom->v, **omega = atom->omega;
  int m = 0;
  for (int k = 0; k < count; k++) {
    const int j = list[k];
    for (int c = 0; c < 3; c++) buf[m++] = v[j][c];
    for (int c = 0; c < 3; c++) buf[m++] = omega[j][c];
  }
#ifdef SERVO_BC_LIGGGHTS
  return 6;    // LIGGGHTS 3.8's pack_comm returns the values per atom
#else
  return m;    // LAMMPS' pack_forward_comm returns them all
#endif
}

#ifdef SERVO_BC_LIGGGHTS
void FixServoBCBonds::unpack_comm(int count, int first, double *buf)
#else
void FixServoBCBonds::unpack_forward_comm(int count, int first, double *buf)
#endif
{
  double **v = atom->v, **omega = atom->omega;
  int m = 0;
  for (int i = first; i < first + count; i++) {
    for (int c = 0; c < 3; c++) v[i][c] = buf[m++];
    for (int c = 0; c < 3; c++) omega[i][c] = buf[m++];
  }
}
