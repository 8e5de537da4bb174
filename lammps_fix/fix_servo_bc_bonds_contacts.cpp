/* ----------------------------------------------------------------------
   fix servo_bc/bonds cohesive: every contact of the group kept with its
   atoms (fix_servo_bc_bonds.h). The per-atom slots of
   fix_servo_bc_bonds_slots.cpp hold, per pair whose state is not all 0 (an
   intact bond, or a contact with a tangential spring), the partner's ID and
   the pair's state (cohesive_host.h: intact, fs, m); both atoms keep a copy.
   At each neighbour build the owned atoms' pairs are found again: the
   group's discs closer than R_a + R_b + the neighbour skin (the core's
   grid) and every intact bond, each with the state its slot kept. Between
   builds the pairs advance in this list; their states go back into the
   slots before atoms migrate or are written (sync_contacts).
------------------------------------------------------------------------- */

#include "fix_servo_bc_bonds.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "group.h"
#include "memory.h"
#include "neighbor.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

using namespace LAMMPS_NS;

namespace {
constexpr int PER = SBC_COHESIVE_PAIR_STATE;
}

/* the ghost cutoff of this rank's communication, m */
double FixServoBCBonds::ghost_cutoff() const
{
  return std::min(comm->cutghost[0], std::min(comm->cutghost[1], comm->cutghost[2]));
}

/* the first run: the slots' size from the group's radii, then the pairs,
   bonded where the discs touch (build_contacts) */
void FixServoBCBonds::create_contacts()
{
  double rmax, mmin;
  survey_group(rmax, mmin);
  // the most discs of radius >= r_min that touch one of r_max without overlapping each other, and 2 to spare
  maxb = (int) std::floor(M_PI / std::asin(rmin / (rmax + rmin))) + 2;
  per = PER;
  size_slots();
  build_contacts(true);
}

/* the owned atoms' pairs at a neighbour build: candidates within the skin
   and every intact bond of the slots, each with its slot's state (fresh:
   the first run, bonded where the discs touch) */
void FixServoBCBonds::build_contacts(bool fresh)
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  double **x = atom->x, *radius = atom->radius;
  tagint *tag = atom->tag;
  // every reach a pair needs: a contact within the skin, an intact bond up to eq. 8's stretch fn / kn
  double rmax = 0.0;
  for (int i = 0; i < nlocal; i++)
    if (atom->mask[i] & groupbit) rmax = std::max(rmax, radius[i]);
  double reach = 0.0;
  MPI_Allreduce(&rmax, &reach, 1, MPI_DOUBLE, MPI_MAX, world);
  const double skin = neighbor->skin, stretch = law.fn_u / law.kn;
  reach = 2.0 * reach + std::max(skin, stretch);
  if ((comm->nprocs > 1 || domain->xperiodic || domain->yperiodic) && ghost_cutoff() < reach * (1.0 - 1e-9))
    fail("the ghost cutoff " + std::to_string(ghost_cutoff()) + " m is shorter than a pair's reach " +
         std::to_string(reach) + " m (2 r_max + max(neighbour skin, fn / kn)); raise it (comm_modify cutoff or the "
         "pair style's cutoff in LAMMPS, communicate single cutoff in LIGGGHTS)");

  std::vector<int> at;
  std::vector<double> xs, rs;
  for (int i = 0; i < nall; i++)
    if (atom->mask[i] & groupbit) {
      at.push_back(i);
      xs.insert(xs.end(), {x[i][0], x[i][1]});
      rs.push_back(radius[i]);
    }
  int *pairs = nullptr;
  char msg[512] = "";
  const long np = sbc_cohesive_host_pairs((int) at.size(), xs.data(), rs.data(), skin, &pairs, msg, sizeof msg);
  if (np < 0) fail_here(msg);
  struct Entry {
    int i, j;
    tagint partner;
    double dd;    // |x_j - x_i|^2: the closest image of a partner is the pair
  };
  std::vector<Entry> entries;
  auto add = [&](int i, int j) {
    const double dx = x[j][0] - x[i][0], dy = x[j][1] - x[i][1];
    entries.push_back({i, j, tag[j], dx * dx + dy * dy});
  };
  for (long p = 0; p < np; p++) {
    const int a = at[pairs[2 * p]], b = at[pairs[2 * p + 1]];
    if (a < nlocal) add(a, b);
    if (b < nlocal) add(b, a);
  }
  sbc_cohesive_host_pairs_free(pairs);
  auto by_atom = [](const Entry &p, const Entry &q) {
    return p.i != q.i ? p.i < q.i : p.partner != q.partner ? p.partner < q.partner : p.dd < q.dd;
  };
  std::sort(entries.begin(), entries.end(), by_atom);
  // the slots' intact bonds: kept however far they stretched, their partner owned or a ghost
  if (!fresh) {
    const size_t candidates = entries.size();
    bool mapped = false;
    for (int i = 0, e = 0; i < nlocal; i++) {
      if (!(atom->mask[i] & groupbit)) continue;
      while (e < (int) candidates && entries[e].i < i) e++;
      const int count = (int) slot[i][0];
      for (int s = 0; s < count; s++) {
        const double *rec = &slot[i][1 + s * (1 + PER)];
        if (rec[1] == 0.0) continue;    // a contact only: within the skin if it still touches
        const tagint t = (tagint) rec[0];
        bool listed = false;
        for (int g = e; g < (int) candidates && entries[g].i == i && !listed; g++) listed = entries[g].partner == t;
        if (listed) continue;
        if (!mapped) map_images();    // atom ID -> its owned and ghost indices (fix_servo_bc_bonds_slots.cpp)
        mapped = true;
        const int j = partner(t, x[i]);
        if (j < 0)
          fail_here("the bond of atoms " + std::to_string((long) tag[i]) + " and " + std::to_string((long) t) +
                    ": atom " + std::to_string((long) t) + " is neither owned by rank " + std::to_string(comm->me) +
                    " nor one of its ghosts (ghost cutoff " + std::to_string(ghost_cutoff()) +
                    " m): raise it (comm_modify cutoff in LAMMPS, communicate single cutoff in LIGGGHTS)");
        add(i, j);
      }
    }
    if (entries.size() > candidates) std::sort(entries.begin(), entries.end(), by_atom);
  }
  // one entry per owned atom and partner ID, the closest image
  entries.erase(std::unique(entries.begin(), entries.end(),
                            [](const Entry &p, const Entry &q) { return p.i == q.i && p.partner == q.partner; }),
                entries.end());
  // the pairs, each once: end A first; those whose end A is owned before the others
  std::vector<int> ends[2];
  std::vector<double> states[2];
  for (const Entry &e : entries) {
    if (e.j < nlocal && tag[e.i] > tag[e.j]) continue;    // both owned: the pair is its end A's entry
    const int a = tag[e.i] < tag[e.j] ? e.i : e.j, b = a == e.i ? e.j : e.i, side = a < nlocal ? 0 : 1;
    double state[PER] = {0.0, 0.0, 0.0};
    if (fresh)
      sbc_cohesive_pair_start(x[a], radius[a], x[b], radius[b], rmin, state);
    else {
      const int count = (int) slot[e.i][0];
      for (int s = 0; s < count; s++)
        if ((tagint) slot[e.i][1 + s * (1 + PER)] == e.partner) {
          std::memcpy(state, &slot[e.i][2 + s * (1 + PER)], sizeof state);
          break;
        }
    }
    ends[side].insert(ends[side].end(), {a, b});
    states[side].insert(states[side].end(), state, state + PER);
  }
  pairs_counted = (long) ends[0].size() / 2;
  pair_ends.swap(ends[0]);    // the counted pairs stay where they were built, the others follow
  pair_ends.insert(pair_ends.end(), ends[1].begin(), ends[1].end());
  pair_state.swap(states[0]);
  pair_state.insert(pair_state.end(), states[1].begin(), states[1].end());
  const long npairs = (long) pair_ends.size() / 2;
  // each owned atom's loads summed in its partners' ID order, so that the sums, and so the results, do not
  // depend on which partners are ghosts (the rank count)
  std::vector<std::pair<tagint, int>> refs;    // per owned atom: (partner ID, the load's offset)
  load_start.assign(nlocal + 1, 0);
  for (long k = 0; k < npairs; k++)
    for (int end = 0; end < 2; end++)
      if (pair_ends[2 * k + end] < nlocal) load_start[pair_ends[2 * k + end] + 1]++;
  for (int i = 0; i < nlocal; i++) load_start[i + 1] += load_start[i];
  refs.resize(load_start[nlocal]);
  std::vector<int> fill(load_start.begin(), load_start.end() - 1);
  for (long k = 0; k < npairs; k++)
    for (int end = 0; end < 2; end++) {
      const int i = pair_ends[2 * k + end];
      if (i < nlocal) refs[fill[i]++] = {tag[pair_ends[2 * k + 1 - end]], (int) (6 * k + 3 * end)};
    }
  load_at.resize(refs.size());
  for (int i = 0; i < nlocal; i++) {
    std::sort(refs.begin() + load_start[i], refs.begin() + load_start[i + 1]);
    for (int r = load_start[i]; r < load_start[i + 1]; r++) load_at[r] = refs[r].second;
  }
  contact_load.assign(6 * npairs, 0.0);
  if (!fresh) return;
  int mine = 0;
  for (long k = 0; k < pairs_counted; k++) mine += pair_state[PER * k] != 0.0;
  MPI_Allreduce(&mine, &formed, 1, MPI_INT, MPI_SUM, world);
  if (formed == 0)
    fail("cohesive: no two of the " + std::to_string(n) + " discs touch, so no bond formed (group " +
         group->names[igroup] + ")");
  have_contacts = true;
  copies_stale = true;    // the new bonds into the slots
  sync_contacts();
  char line[256];
  std::snprintf(line, sizeof line, "fix servo_bc/bonds: %d cohesive bonds (%d formed) between %d discs\n", formed,
                formed, n);
  say(line);
}

/* one step of every pair of the owned atoms (motion false: a run's setup
   sees the last configuration again, with no motion, so the states keep
   their loads); relax.h's sums over the pairs whose end A is owned */
void FixServoBCBonds::step_contacts(bool motion)
{
  if (motion && !comm->ghost_velocity) comm->forward_comm_fix(this);    // v, omega of the ghosts
  double **f = atom->f, **torque = atom->torque;
  const double *v = motion ? &atom->v[0][0] : nullptr, *w = motion ? &atom->omega[0][2] : nullptr;
  const double *x = &atom->x[0][0], dt = update->dt;
  double sums4[4] = {0.0, 0.0, 0.0, 0.0};
  const long npairs = (long) pair_ends.size() / 2;
  // x, v and omega are rows of 3 doubles (LAMMPS' and LIGGGHTS' per-atom arrays are contiguous)
  intact_mine = (int) sbc_cohesive_pairs_step(&law, pairs_counted, pair_ends.data(), x, v, 3, w, 3, atom->radius, dt,
                                              pair_state.data(), contact_load.data(), sums4);
  sbc_cohesive_pairs_step(&law, npairs - pairs_counted, pair_ends.data() + 2 * pairs_counted, x, v, 3, w, 3,
                          atom->radius, dt, pair_state.data() + PER * pairs_counted,
                          contact_load.data() + 6 * pairs_counted, nullptr);
  for (int i = 0; i < atom->nlocal; i++) {
    double acc[3] = {0.0, 0.0, 0.0};
    for (int r = load_start[i]; r < load_start[i + 1]; r++)
      for (int q = 0; q < 3; q++) acc[q] += contact_load[load_at[r] + q];
    f[i][0] += acc[0];
    f[i][1] += acc[1];
    torque[i][2] += acc[2];
  }
  for (int k = 0; k < 4; k++)
    if (!std::isfinite(sums4[k]))
      fail_here("a contact load is not finite at step " + std::to_string((long) update->ntimestep) +
                " (time step " + std::to_string(dt) + " s; the critical step is 2 sqrt(m_min / (2 kn)))");
  std::copy(sums4, sums4 + 4, contact_mine);
  copies_stale = true;    // the slots lag the pairs
  reduced_at = -1;
}

/* every pair's state back into the slots of its owned atoms: before atoms
   migrate (pre_exchange), at a run's end and before restart data are
   written; a pair whose state is all 0 is forgotten */
void FixServoBCBonds::sync_contacts()
{
  if (!copies_stale) return;    // the slots hold every state (after a sync, a restart file or before a build)
  copies_stale = false;
  const int nlocal = atom->nlocal;
  tagint *tag = atom->tag;
  for (int i = 0; i < nlocal; i++) slot[i][0] = 0.0;
  auto keep = [&](int i, tagint partner, const double *state) {
    const int s = (int) slot[i][0];
    if (s == maxb)
      fail_here("atom " + std::to_string((long) tag[i]) + " has more than " + std::to_string(maxb) +
                " bonds and contacts with a tangential spring (the slots sized at the first run from the group's "
                "radii, r_min " + std::to_string(rmin) + " m)");
    double *rec = &slot[i][1 + s * (1 + PER)];
    rec[0] = (double) partner;
    std::memcpy(&rec[1], state, sizeof(double) * PER);
    slot[i][0] = s + 1;
  };
  const long npairs = (long) pair_ends.size() / 2;
  for (long k = 0; k < npairs; k++) {
    const double *state = &pair_state[PER * k];
    if (state[0] == 0.0 && state[1] == 0.0 && state[2] == 0.0) continue;
    const int a = pair_ends[2 * k], b = pair_ends[2 * k + 1];
    if (a < nlocal) keep(a, tag[b], state);
    if (b < nlocal) keep(b, tag[a], state);
  }
}
