/* fix servo_bc's restart data (LAMMPS and LIGGGHTS, as fix_servo_bc.cpp): the
   global block, sealed (sbc/saved.h), and the per-atom rotations and remap
   velocities */
#include "fix_servo_bc.h"

#include "comm.h"
#include "atom.h"

#include <cstdint>
#include <vector>

using namespace LAMMPS_NS;

namespace {
// marks fix servo_bc's restart block (and its layout: bump on any change)
const double RESTART_MAGIC = 8.020002e7;
}    // namespace

/* global restart data, written by rank 0: frame, atom IDs, masses, controller
   state, finished flag */
void FixServoBC::write_restart(FILE *fp)
{
  if (comm->me != 0) return;
  std::vector<double> list;
  list.push_back(RESTART_MAGIC);
  list.resize(1 + SBC_SEALED_HEAD);    // the seal's head, set below (sbc/saved.h)
  list.push_back((double) sbc_frame_state_size(&frame));
  size_t at = list.size();
  list.resize(at + sbc_frame_state_size(&frame));
  sbc_frame_save(&frame, &list[at]);
  for (int q = 0; q < frame.n; q++) list.push_back((double) frame_tag[q]);
  for (int q = 0; q < frame.n; q++) list.push_back(frame_mass[q]);
  size_t nc = ctl ? sbc_controller_state_size(ctl) : 0;
  list.push_back((double) nc);
  at = list.size();
  list.resize(at + nc);
  if (ctl) sbc_controller_save(ctl, &list[at]);
  list.push_back(finished);
  list.push_back((double) last_step);
  const sbc_fire_state &now = driver ? *sbc_driver_fire(driver) : fire;
  list.push_back(now.alpha);
  list.push_back((double) now.positive);
  sbc_saved_seal(&list[1], list.size() - 1);
  int bytes = (int) (list.size() * sizeof(double));    // LAMMPS reads the block size in bytes
  fwrite(&bytes, sizeof(int), 1, fp);
  fwrite(list.data(), sizeof(double), list.size(), fp);
}

void FixServoBC::restart(char *raw)
{
  // every value is checked before it is used (sbc/saved.h): a restart file
  // may be truncated, corrupted or from another version
  const double *list = (const double *) raw;
  sbc_error err;
  sbc_saved rd;
  if (list[0] != RESTART_MAGIC)
    fail("restart: the saved fix servo_bc data is not this version's (write the restart file again)");
  // its length and every value after it are sealed: a changed value is refused before any is used
  size_t total = 0;
  if (sbc_saved_open(list + 1, SIZE_MAX, &total, "restart: fix servo_bc data", &err) != SBC_OK) fail(err.message);
  sbc_saved_start(&rd, list + 1 + SBC_SEALED_HEAD, total - SBC_SEALED_HEAD, "fix servo_bc restart data", &err);
  const size_t nf = (size_t) sbc_saved_int(&rd, "frame length", 1, (long) rd.n);
  if (rd.st != SBC_OK) fail(err.message);
  sbc_frame_free(&frame);
  if (sbc_frame_load(&frame, rd.in + rd.at, nf, &err) != SBC_OK) fail(err.message);
  rd.at += nf;
  frame_tag.resize(frame.n);
  frame_mass.resize(frame.n);
  for (int q = 0; q < frame.n; q++) frame_tag[q] = (tagint) sbc_saved_int(&rd, "frame atom ID", 1, MAXTAGINT);
  for (int q = 0; q < frame.n; q++) frame_mass[q] = sbc_saved_positive(&rd, "frame mass");
  const size_t nc = (size_t) sbc_saved_int(&rd, "controller length", 0, (long) (rd.n - rd.at));
  if (rd.st != SBC_OK) fail(err.message);
  saved_state.assign(rd.in + rd.at, rd.in + rd.at + nc);
  rd.at += nc;
  finished = (int) sbc_saved_int(&rd, "finished", 0, 1);
  last_step = (bigint) sbc_saved_int(&rd, "last step", -1, 1125899906842624L);
  fire.alpha = sbc_saved_positive(&rd, "FIRE alpha");
  fire.positive = sbc_saved_int(&rd, "FIRE steps", 0, 1125899906842624L);
  if (rd.st != SBC_OK) fail(err.message);
  if (rd.at != rd.n)
    fail("restart: fix servo_bc data: " + std::to_string(rd.n - rd.at) + " values follow its last field (FIRE steps)");
  restored = 1;
  make_buffers();
}

/* per-atom restart data: the accumulated rotation (nrot components), then
   the velocity of keyword remap x to be taken back (3 components; files
   written before remap existed end after the rotation) */
int FixServoBC::pack_restart(int i, double *out)
{
  out[0] = 1 + nrot + 3;
  for (int c = 0; c < nrot; c++) out[1 + c] = per_atom[i][1 + c];
  for (int c = 0; c < 3; c++) out[1 + nrot + c] = stream[i][c];
  return 1 + nrot + 3;
}

void FixServoBC::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  int m = 0;
  for (int i = 0; i < nth; i++) m += static_cast<int>(extra[nlocal][m]);
  const int size = static_cast<int>(extra[nlocal][m++]);
  for (int c = 0; c < nrot; c++) per_atom[nlocal][1 + c] = extra[nlocal][m + c];
  for (int c = 0; c < 3; c++) stream[nlocal][c] = size == 1 + nrot + 3 ? extra[nlocal][m + nrot + c] : 0.0;
  if (size == 1 + nrot + 3)
    for (int c = 0; c < 3; c++) streaming |= stream[nlocal][c] != 0.0;
}

int FixServoBC::size_restart(int)
{
  return 1 + nrot + 3;
}

int FixServoBC::maxsize_restart()
{
  return 1 + nrot + 3;
}
