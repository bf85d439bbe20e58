/* ----------------------------------------------------------------------
   fix couple/coarse -- DEM side of the in-process CFD-DEM coupling of the
   coarse-particle coupling plugin (coarse-dem).

   LIGGGHTS is free software under the GNU GPL v2 or later; this file is
   distributed under the same terms so that it can be compiled into LIGGGHTS.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------

Syntax:

   fix ID group-ID couple/coarse keyword value ...

   ID, group-ID are documented in the fix command
   couple/coarse = style name of this fix command
   zero or more keyword/value pairs may be appended
   keyword = apply or check_order

     apply value = yes or no
       yes = add the stored coupling force to each particle every time step (default)
       no  = store the forces (for total_force() and the fix output) but do not add
             them to the particles: they move as in a DEM-only run while the CFD side
             still applies the reaction to the fluid (a diagnostic, e.g. to see what the
             fluid does to a bed held by the DEM alone; not one-way coupling, which
             would leave the fluid without the reaction)
     check_order value = yes or no
       yes = push_forces() verifies that the local particles are still those of the
             last pull(), in the same order, and stops with an error otherwise (default)
       no  = skip that check (saves one pass over the particles)

Examples:

   fix cpl all couple/coarse
   fix cpl all couple/coarse apply no
   fix cpl all couple/coarse check_order no

Description:

This fix is the DEM side of the in-process coupling between LIGGGHTS and the
coarse-particle CFD solver. LIGGGHTS runs as a library inside the CFD solver's
process, on the same MPI ranks (see coarseDemFoam). The solver finds this fix
through lmp->modify and, every coupling interval, it

  1. calls pull() to copy position, velocity, radius, density, type and ID of
     the particles in the fix group that this rank owns;
  2. computes the fluid-particle force on each of them (drag, pressure
     gradient, ...);
  3. calls push_forces() with one force vector per particle, in the order of
     the pull(), and (optionally) push_drag() with a drag coefficient and the
     fluid velocity per particle;
  4. calls begin_segment() and advances the DEM with "run N pre no post no":
     LIGGGHTS' setup (a neighbour-list build and a force evaluation every
     segment) is needed only when something else changed the DEM between
     segments (the solver then runs "pre yes").

The pushed force of every particle is stored in a per-atom array that travels
with the particle when it migrates to another processor or when LIGGGHTS sorts
its atoms. The fix adds it to the particle's force in post_force() of every
DEM time step until the next push_forces() replaces it. Particles created
after the last push (e.g. by fix insert/pack) start with a zero force.

The fix computes a per-atom array of 3 columns: the coupling force each
particle got at the last time step (zero outside the group and with apply no);
dump custom writes it as f_ID[1], f_ID[2], f_ID[3]. A dump of it shows which
particles the fluid carries and which rest on their contacts.

The fix computes a global vector of length 3: the sum over all processors of
the stored coupling force of the particles in the group (force units). It can
be printed with thermo_style custom as f_ID[1], f_ID[2], f_ID[3]. It is an
extensive quantity.

The stored forces and drag data are written to restart files, so that a restarted run
applies the forces of the last coupling step until the solver pushes new ones.

Public C++ interface (used by the solver; "local" means owned by this rank and
in the fix group, in LIGGGHTS' local atom order at the time of the call):

   int  nlocal() const;       number of local particles
   void pull(double *x, double *v, double *radius, double *density,
             int *type, long long *id);
        x, v: 3*nlocal() values (x0 y0 z0 x1 ...); radius, density, type,
        id: nlocal() values. Any pointer may be NULL to skip that quantity.
   void push_forces(const double *f);
        3*nlocal() values, per particle in the order of the last pull().
        Must be called before the next DEM step after the pull (the local
        order changes during a run). It clears the drag part (push_drag).
   void push_drag(const double *K, const double *ufluid);
        optional, after push_forces(): per particle a drag coefficient K (kg/s,
        nlocal() values) and the fluid velocity at the particle (3*nlocal()
        values), in the order of the last pull(). Until the next push the
        particle then gets, every DEM step, K (u_fluid - v) with its current
        velocity v on top of the pushed force: the drag relaxes with the DEM
        step and stays stable when the coupling interval is longer than the
        particle response time m/K.
   void begin_segment(bigint nsteps, int refresh, int migrate);
        before a DEM segment of nsteps steps. refresh (a segment without setup):
        the force on each particle still holds the coupling force of the last
        step; it is replaced by the one just pushed, at the current velocity, as
        the setup would, so the first half-kick uses it and coupling_impulse()
        counts from it. migrate (a parallel run): the segment's last step
        rebuilds the neighbour lists, so that every particle is held by the rank
        of its sub-domain when the solver pulls them after the segment.
        The refresh assumes that no fix after this one overwrites the force
        (setforce, freeze, aveforce): with such a fix the solver starts every
        segment with a setup ("run N pre yes").
   void total_force(double out[3]) const;
        sum of the coupling force (stored force + drag part at the current
        velocities) over the local particles (no MPI communication).
   void coupling_impulse(double out[3]) const;
        impulse (force x time) the coupling forces gave the local particles
        since the last push_forces(), as velocity Verlet applies them: each
        force evaluation counts for the half-steps that use it (no MPI
        communication; the sum over the ranks is the global impulse).

Restrictions:

Requires atom style sphere or granular (per-atom radius and density).
Particles outside the fix group get no coupling force and are not pulled.
The fix does not support run styles respa or energy minimisation.

Related commands:

   fix gravity, fix addforce

Default:

   apply = yes, check_order = yes

------------------------------------------------------------------------- */

#ifdef FIX_CLASS

FixStyle(couple/coarse,FixCoupleCoarse)

#else

#ifndef LMP_FIX_COUPLE_COARSE_H
#define LMP_FIX_COUPLE_COARSE_H

#include "fix.h"

namespace LAMMPS_NS {

class FixCoupleCoarse : public Fix {
 public:
  FixCoupleCoarse(class LAMMPS *, int, char **);
  ~FixCoupleCoarse();

  // LIGGGHTS/LAMMPS fix interface
  int setmask();
  void init();
  void setup(int);
  void post_force(int);
  double compute_vector(int);
  double memory_usage();

  void grow_arrays(int);
  void copy_arrays(int, int, int);
  void set_arrays(int);
  int pack_exchange(int, double *);
  int unpack_exchange(int, double *);
  int pack_restart(int, double *);
  void unpack_restart(int, int);
  int size_restart(int);
  int maxsize_restart();

  // coupling interface (called by the CFD solver in the same process)
  int nlocal() const;
  void pull(double *x, double *v, double *radius, double *density, int *type, long long *id);
  void push_forces(const double *f);
  void push_drag(const double *K, const double *ufluid);
  void begin_segment(bigint nsteps, int refresh, int migrate);
  void total_force(double out[3]) const;
  void coupling_impulse(double out[3]) const;

  // number of pull() and push_forces() calls so far (for diagnostics)
  long long n_pulls() const { return npull_; }
  long long n_pushes() const { return npush_; }

 private:
  // per-atom coupling data, [atom->nmax][NDATA]: force (3), drag coefficient K, fluid velocity (3)
  enum { NDATA = 7 };
  double **fcoupling_;
  double **fapplied_;    // [atom->nmax][3]: the coupling force added at the last step (output)
  int apply_;            // 1: add fcoupling_ to f in post_force
  int check_order_;      // 1: push_forces checks that atoms are those of the last pull

  // state of the last pull(), used to check push_forces()
  int *pulled_tag_;      // tags of the pulled atoms, in pull order
  int npulled_;          // number of atoms pulled
  int maxpulled_;        // allocated length of pulled_tag_
  bigint pull_step_;     // update->ntimestep at the last pull (-1: none)
  long long npull_, npush_;

  // impulse given since the last push_forces(), and the sum of the coupling forces of the last
  // evaluation (the first half-kick of the next step uses them)
  double impulse_[3];
  double last_applied_[3];

  int in_group(int i) const;
  void coupling_force(int i, double out[3]) const;   // force + K (u_fluid - v)
  void add_coupling_forces(double sum[3]);
};

}

#endif
#endif

/* ERROR/WARNING messages:

E: Illegal fix couple/coarse command: unknown keyword ...

The keyword is not one of apply, check_order.

E: Illegal fix couple/coarse command: keyword ... expects yes or no

Self-explanatory.

E: Fix couple/coarse requires atom attributes radius, rmass, density

Use atom_style sphere or granular.

E: Fix couple/coarse: push_forces() without a preceding pull()

The solver must pull the particles before it pushes their forces.

E: Fix couple/coarse: particles changed between pull() and push_forces()

A DEM step ran, or particles were added/removed/reordered, between the two
calls. The solver must push the forces before the next "run".

*/
