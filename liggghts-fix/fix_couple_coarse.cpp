/* ----------------------------------------------------------------------
   fix couple/coarse -- DEM side of the in-process CFD-DEM coupling of the
   coarse-particle coupling plugin (coarse-dem). Documentation: see the
   header fix_couple_coarse.h.

   LIGGGHTS is free software under the GNU GPL v2 or later; this file is
   distributed under the same terms so that it can be compiled into LIGGGHTS.
------------------------------------------------------------------------- */

#include "fix_couple_coarse.h"

#include <mpi.h>
#include <stdio.h>
#include <string.h>

#include "atom.h"
#include "error.h"
#include "memory.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace FixConst;

namespace {

// Parse a yes/no keyword value; stops with a LIGGGHTS error otherwise.
int yes_no(Error *error, const char *keyword, const char *value)
{
  if (strcmp(value, "yes") == 0) return 1;
  if (strcmp(value, "no") == 0) return 0;
  char msg[256];
  snprintf(msg, sizeof(msg),
           "Illegal fix couple/coarse command: keyword %s expects yes or no, got '%s'",
           keyword, value);
  error->all(FLERR, msg);
  return 0;
}

}  // namespace

/* ---------------------------------------------------------------------- */

FixCoupleCoarse::FixCoupleCoarse(LAMMPS *lmp, int narg, char **arg) :
  Fix(lmp, narg, arg),
  fcoupling_(NULL),
  fapplied_(NULL),
  apply_(1),
  check_order_(1),
  pulled_tag_(NULL),
  npulled_(0),
  maxpulled_(0),
  pull_step_(-1),
  npull_(0),
  npush_(0)
{
  for (int d = 0; d < 3; d++) impulse_[d] = last_applied_[d] = 0.0;
  // arg[0..2] = ID group-ID couple/coarse; then keyword/value pairs
  int iarg = 3;
  while (iarg < narg) {
    if (iarg + 1 >= narg) {
      char msg[256];
      snprintf(msg, sizeof(msg),
               "Illegal fix couple/coarse command: keyword %s needs a value", arg[iarg]);
      error->all(FLERR, msg);
    }
    if (strcmp(arg[iarg], "apply") == 0) {
      apply_ = yes_no(error, arg[iarg], arg[iarg + 1]);
    } else if (strcmp(arg[iarg], "check_order") == 0) {
      check_order_ = yes_no(error, arg[iarg], arg[iarg + 1]);
    } else {
      char msg[256];
      snprintf(msg, sizeof(msg),
               "Illegal fix couple/coarse command: unknown keyword '%s' "
               "(valid keywords: apply, check_order)", arg[iarg]);
      error->all(FLERR, msg);
    }
    iarg += 2;
  }

  if (!atom->radius_flag || !atom->rmass_flag || !atom->density_flag)
    error->all(FLERR, "Fix couple/coarse requires atom attributes radius, rmass, density "
                      "(atom_style sphere or granular)");

  // global output: total coupling force (3 components, extensive)
  vector_flag = 1;
  size_vector = 3;
  global_freq = 1;
  extvector = 1;

  // per-atom output: the coupling force each particle got at the last DEM step (3 columns,
  // f_ID[1..3] in dump custom), so that a dump shows where the fluid carries the particles
  // and where their contacts do
  peratom_flag = 1;
  size_peratom_cols = 3;
  peratom_freq = 1;

  // per-atom state travels with atoms (exchange, sorting) and into restart files;
  // new atoms (inserted particles) get a zero force via set_arrays
  restart_peratom = 1;
  create_attribute = 1;

  // LIGGGHTS' Modify::setup() calls set_arrays() for every atom of a fix that is "just
  // created" and has create_attribute, i.e. at the first run after this command. That would
  // wipe forces pushed before the first run. The atoms existing now are zeroed below, so
  // that first-setup pass is not needed (fix rigid does the same).
  just_created = 0;

  // begin_segment() can ask for a neighbour-list build at a segment's last step (Neighbor::decide
  // checks next_reneighbor of the fixes that force reneighbouring)
  force_reneighbor = 1;
  next_reneighbor = -1;

  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow/copy/exchange
  atom->add_callback(1);  // restart

  for (int i = 0; i < atom->nmax; i++) set_arrays(i);
}

/* ---------------------------------------------------------------------- */

FixCoupleCoarse::~FixCoupleCoarse()
{
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(fcoupling_);
  memory->destroy(fapplied_);
  memory->destroy(pulled_tag_);
}

/* ---------------------------------------------------------------------- */

int FixCoupleCoarse::setmask()
{
  int mask = 0;
  mask |= POST_FORCE;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixCoupleCoarse::init()
{
  if (strstr(update->integrate_style, "respa"))
    error->all(FLERR, "Fix couple/coarse does not support run_style respa");
}

/* ----------------------------------------------------------------------
   setup: the forces of this fix are part of the force on each atom from
   the first step on, like every post_force fix
------------------------------------------------------------------------- */

void FixCoupleCoarse::setup(int)
{
  // the setup's force gives the first half-kick of the run's first step (velocity Verlet), which
  // post_force() of that step counts
  add_coupling_forces(last_applied_);
}

/* ----------------------------------------------------------------------
   post_force: add the coupling force and count the impulse it gives. Velocity
   Verlet uses each force evaluation for the second half-kick of its step and the
   first half-kick of the next one, so the impulse of step k is
   dt/2 (sum of the forces of the previous evaluation + sum of this one);
   the previous evaluation is the setup's for the first step of a run.
------------------------------------------------------------------------- */

void FixCoupleCoarse::post_force(int)
{
  double sum[3];
  add_coupling_forces(sum);
  const double half_dt = 0.5 * update->dt;
  for (int d = 0; d < 3; d++) {
    impulse_[d] += half_dt * (last_applied_[d] + sum[d]);
    last_applied_[d] = sum[d];
  }
}

// adds the coupling force to every local particle of the group (nothing with apply no) and
// returns the sum of what it added; keeps each particle's force for the per-atom output
void FixCoupleCoarse::add_coupling_forces(double sum[3])
{
  sum[0] = sum[1] = sum[2] = 0.0;
  double **f = atom->f;
  int *mask = atom->mask;
  const int n = atom->nlocal;
  for (int i = 0; i < n; i++) {
    double fi[3] = {0.0, 0.0, 0.0};
    if (apply_ && (mask[i] & groupbit)) {
      coupling_force(i, fi);
      for (int d = 0; d < 3; d++) {
        f[i][d] += fi[d];
        sum[d] += fi[d];
      }
    }
    for (int d = 0; d < 3; d++) fapplied_[i][d] = fi[d];
  }
}

/* ----------------------------------------------------------------------
   global vector: total stored coupling force over all procs
   (collective: thermo output calls it on every proc)
------------------------------------------------------------------------- */

double FixCoupleCoarse::compute_vector(int n)
{
  double local[3], all[3];
  total_force(local);
  MPI_Allreduce(local, all, 3, MPI_DOUBLE, MPI_SUM, world);
  if (n < 0 || n > 2) return 0.0;
  return all[n];
}

/* ---------------------------------------------------------------------- */

double FixCoupleCoarse::memory_usage()
{
  return double(NDATA + 3) * atom->nmax * sizeof(double) + maxpulled_ * sizeof(int);
}

/* ----------------------------------------------------------------------
   per-atom array bookkeeping (called by Atom through the callbacks)
------------------------------------------------------------------------- */

void FixCoupleCoarse::grow_arrays(int nmax)
{
  memory->grow(fcoupling_, nmax, NDATA, "fix_couple_coarse:fcoupling");
  memory->grow(fapplied_, nmax, 3, "fix_couple_coarse:fapplied");
  array_atom = fapplied_;
}

void FixCoupleCoarse::copy_arrays(int i, int j, int)
{
  for (int d = 0; d < NDATA; d++) fcoupling_[j][d] = fcoupling_[i][d];
  for (int d = 0; d < 3; d++) fapplied_[j][d] = fapplied_[i][d];
}

void FixCoupleCoarse::set_arrays(int i)
{
  for (int d = 0; d < NDATA; d++) fcoupling_[i][d] = 0.0;
  for (int d = 0; d < 3; d++) fapplied_[i][d] = 0.0;
}

// the exchange record must have the same length on both sides (NDATA values)
int FixCoupleCoarse::pack_exchange(int i, double *buf)
{
  for (int d = 0; d < NDATA; d++) buf[d] = fcoupling_[i][d];
  return NDATA;
}

int FixCoupleCoarse::unpack_exchange(int nlocal, double *buf)
{
  for (int d = 0; d < NDATA; d++) fcoupling_[nlocal][d] = buf[d];
  return NDATA;
}

// restart record per atom: [length = NDATA + 1, fx, fy, fz, K, ufx, ufy, ufz]
int FixCoupleCoarse::pack_restart(int i, double *buf)
{
  buf[0] = NDATA + 1;
  for (int d = 0; d < NDATA; d++) buf[1 + d] = fcoupling_[i][d];
  return NDATA + 1;
}

void FixCoupleCoarse::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // skip the records of the fixes before this one
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  m++;
  for (int d = 0; d < NDATA; d++) fcoupling_[nlocal][d] = extra[nlocal][m++];
}

int FixCoupleCoarse::size_restart(int)
{
  return NDATA + 1;
}

int FixCoupleCoarse::maxsize_restart()
{
  return NDATA + 1;
}

/* ----------------------------------------------------------------------
   coupling interface
------------------------------------------------------------------------- */

int FixCoupleCoarse::in_group(int i) const
{
  return (atom->mask[i] & groupbit) != 0;
}

int FixCoupleCoarse::nlocal() const
{
  int n = 0;
  for (int i = 0; i < atom->nlocal; i++)
    if (in_group(i)) n++;
  return n;
}

void FixCoupleCoarse::pull(double *x, double *v, double *radius, double *density,
                           int *type, long long *id)
{
  const int n = nlocal();
  if (n > maxpulled_) {
    maxpulled_ = n;
    memory->grow(pulled_tag_, maxpulled_, "fix_couple_coarse:pulled_tag");
  }

  double **ax = atom->x;
  double **av = atom->v;
  int k = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!in_group(i)) continue;
    if (x) { x[3*k] = ax[i][0]; x[3*k+1] = ax[i][1]; x[3*k+2] = ax[i][2]; }
    if (v) { v[3*k] = av[i][0]; v[3*k+1] = av[i][1]; v[3*k+2] = av[i][2]; }
    if (radius) radius[k] = atom->radius[i];
    if (density) density[k] = atom->density[i];
    if (type) type[k] = atom->type[i];
    if (id) id[k] = static_cast<long long>(atom->tag[i]);
    pulled_tag_[k] = atom->tag[i];
    k++;
  }
  npulled_ = n;
  pull_step_ = update->ntimestep;
  npull_++;
}

void FixCoupleCoarse::push_forces(const double *f)
{
  if (pull_step_ < 0)
    error->one(FLERR, "Fix couple/coarse: push_forces() without a preceding pull()");

  if (check_order_) {
    int same = (update->ntimestep == pull_step_);
    int k = 0;
    for (int i = 0; same && i < atom->nlocal; i++) {
      if (!in_group(i)) continue;
      if (k >= npulled_ || atom->tag[i] != pulled_tag_[k]) same = 0;
      k++;
    }
    if (k != npulled_) same = 0;
    if (!same)
      error->one(FLERR, "Fix couple/coarse: particles changed between pull() and push_forces() "
                        "(a DEM step ran or particles were added, removed or reordered); "
                        "push the forces before the next run");
  }

  int k = 0;
  for (int i = 0; i < atom->nlocal && k < npulled_; i++) {
    if (!in_group(i)) continue;
    fcoupling_[i][0] = f[3*k];
    fcoupling_[i][1] = f[3*k+1];
    fcoupling_[i][2] = f[3*k+2];
    fcoupling_[i][3] = 0.0;   // no drag part until push_drag()
    k++;
  }
  npush_++;
  impulse_[0] = impulse_[1] = impulse_[2] = 0.0;   // these forces start a new impulse count
}

void FixCoupleCoarse::push_drag(const double *K, const double *ufluid)
{
  if (pull_step_ < 0)
    error->one(FLERR, "Fix couple/coarse: push_drag() without a preceding pull()");
  int k = 0;
  for (int i = 0; i < atom->nlocal && k < npulled_; i++) {
    if (!in_group(i)) continue;
    fcoupling_[i][3] = K[k];
    fcoupling_[i][4] = ufluid[3*k];
    fcoupling_[i][5] = ufluid[3*k+1];
    fcoupling_[i][6] = ufluid[3*k+2];
    k++;
  }
}

void FixCoupleCoarse::begin_segment(bigint nsteps, int refresh, int migrate)
{
  if (refresh) {
    // what the setup's force evaluation would give: the force of the last step less the coupling
    // force it holds (fapplied_), plus the one just pushed at the particle's current velocity
    double sum[3] = {0.0, 0.0, 0.0};
    double **f = atom->f;
    int *mask = atom->mask;
    for (int i = 0; i < atom->nlocal; i++) {
      double fi[3] = {0.0, 0.0, 0.0};
      if (apply_ && (mask[i] & groupbit)) coupling_force(i, fi);
      for (int d = 0; d < 3; d++) {
        f[i][d] += fi[d] - fapplied_[i][d];
        fapplied_[i][d] = fi[d];
        sum[d] += fi[d];
      }
    }
    for (int d = 0; d < 3; d++) last_applied_[d] = sum[d];
  }
  next_reneighbor = (migrate && nsteps > 0) ? update->ntimestep + nsteps : -1;
}

// stored force + drag K (u_fluid - v) with the particle's velocity of this DEM step: the drag
// relaxes with the DEM step, so it stays stable when the CFD step exceeds the particle response
// time m/K (a drag force held for the coupling interval overshoots there)
void FixCoupleCoarse::coupling_force(int i, double out[3]) const
{
  const double *c = fcoupling_[i];
  const double *v = atom->v[i];
  out[0] = c[0] + c[3]*(c[4] - v[0]);
  out[1] = c[1] + c[3]*(c[5] - v[1]);
  out[2] = c[2] + c[3]*(c[6] - v[2]);
}

void FixCoupleCoarse::coupling_impulse(double out[3]) const
{
  out[0] = impulse_[0];
  out[1] = impulse_[1];
  out[2] = impulse_[2];
}

void FixCoupleCoarse::total_force(double out[3]) const
{
  out[0] = out[1] = out[2] = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!in_group(i)) continue;
    double fi[3];
    coupling_force(i, fi);
    out[0] += fi[0];
    out[1] += fi[1];
    out[2] += fi[2];
  }
}
