/*
 * coarse_dem.h -- the one public header of the coarse-particle coupling core (the "shim").
 *
 * Pure C11. No OpenFOAM, no LIGGGHTS. The OpenFOAM library, the solver and the LIGGGHTS fix
 * include only this file.
 *
 * What the core does, per coupling step:
 *   1. locate every particle's host cell (walk across faces from a hint cell, spatial-bin fallback);
 *   2. build a KERNEL per particle: a sparse list of (cell, weight), weights >= 0 summing to 1.
 *      The kernel is the single intermediate representation used for everything below;
 *   3. from the kernels: particle volume fraction alpha_p per cell, per-cell force density from
 *      per-particle forces, and volume-weighted background fields at each particle
 *      (Zhang et al., Phys. Fluids 35, 113330 (2023), eqs. 21-22);
 *   4. optional field operations: diffusion smoothing (ibid. eq. 7) and a conservative packing limiter.
 *
 * Conventions:
 *   - every function returns a cdc_status; on error, cdc_last_error(ctx) gives a message naming the
 *     entry or the particle, and the caller's output arrays are left untouched;
 *   - the core never prints, never exits and has no global mutable state; all memory belongs to an
 *     explicit object created and destroyed by the caller; internal buffers are reused across steps;
 *   - mesh arrays are taken by pointer, never copied: they must outlive the context;
 *   - indices are 32-bit (OpenFOAM label size), real numbers are double.
 */
#ifndef COARSE_DEM_H
#define COARSE_DEM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CDC_VERSION_STRING "0.1.0"

typedef enum cdc_status {
    CDC_OK = 0,
    CDC_ERR_ARGUMENT,      /* a NULL pointer, a bad size, a parameter out of range */
    CDC_ERR_NOMEM,         /* an allocation failed */
    CDC_ERR_MESH,          /* the mesh is empty or inconsistent (e.g. a zero-volume cell) */
    CDC_ERR_PARTICLE,      /* a particle has a NaN/infinite position or a radius <= 0 */
    CDC_ERR_OUTSIDE,       /* particles lie outside the mesh (see cdc_kernels_outside) */
    CDC_ERR_KERNEL,        /* a kernel would exceed the whole mesh or is otherwise impossible */
    CDC_ERR_UNKNOWN,       /* unknown method name (message lists the valid ones) */
    CDC_ERR_UNSUPPORTED,   /* method needs a mesh feature this mesh lacks (e.g. exact needs boxes) */
    CDC_ERR_NOT_CONVERGED  /* an iterative solve did not reach its tolerance */
} cdc_status;

/* Kind of a boundary face, as the mesh adapter classifies OpenFOAM patches. */
enum cdc_face_kind {
    CDC_FACE_WALL = 0,      /* physical wall: wall-aware kernels mirror across it */
    CDC_FACE_PROCESSOR = 1, /* processor boundary: the kernel continues on the neighbour rank */
    CDC_FACE_OTHER = 2      /* inlet, outlet, symmetry, empty ...: treated as a domain edge */
};

/*
 * A polyhedral mesh in OpenFOAM's face-addressed form. Faces 0..n_internal_faces-1 are internal
 * (owner < neighbour not required); the rest are boundary faces, each with a kind.
 * Face area vectors point out of the owner cell. Face i's points are
 * face_points[face_point_offsets[i] .. face_point_offsets[i+1]-1].
 */
typedef struct cdc_mesh {
    int32_t n_points;
    int32_t n_cells;
    int32_t n_faces;
    int32_t n_internal_faces;
    const double *points;             /* 3 * n_points */
    const int32_t *face_point_offsets;/* n_faces + 1 */
    const int32_t *face_points;       /* face_point_offsets[n_faces] */
    const int32_t *owner;             /* n_faces */
    const int32_t *neighbour;         /* n_internal_faces */
    const double *face_centres;       /* 3 * n_faces */
    const double *face_areas;         /* 3 * n_faces, area vectors out of the owner */
    const double *cell_centres;       /* 3 * n_cells */
    const double *cell_volumes;       /* n_cells */
    const uint8_t *boundary_face_kind;/* n_faces - n_internal_faces, values of cdc_face_kind */
} cdc_mesh;

/* Particles as the DEM hands them over (structure of arrays, borrowed for the call). */
typedef struct cdc_particles {
    int32_t n;
    const double *position;   /* 3 * n */
    const double *radius;     /* n */
    const int64_t *id;        /* n, DEM ids used in messages; may be NULL (then index is used) */
    int32_t *host_hint;       /* n, in: last host cell or -1; out: host cell or -1 if outside.
                                 May be NULL (no hint, located from scratch every call). */
} cdc_particles;

/* Void-fraction kernel parameters. Zero-initialise, set what the method needs. */
typedef struct cdc_kernel_params {
    double expansion_factor;  /* bigParticle: n >= 1 (0 = original equal split over overlapped cells) */
    double search_factor;     /* twoGrid: search radius / R (default 3 when 0) */
    double bandwidth;         /* gaussian: b > 0 in metres, kernel exp(-r^2/b^2) (Zhang et al. 2023 eq. 6) */
    double cutoff_factor;     /* gaussian: truncation radius / b (default 2 when 0) */
    int wall_mirror;          /* 1: expansion kernels mirror across wall faces (no wall over-concentration) */
} cdc_kernel_params;

/* The members of cdc_kernel_params a method reads, as bits (cdc_method_params): a caller can refuse
 * a parameter given to a method that ignores it (a misspelt or misplaced key). */
enum {
    CDC_PARAM_EXPANSION_FACTOR = 1u << 0,
    CDC_PARAM_SEARCH_FACTOR = 1u << 1,
    CDC_PARAM_BANDWIDTH = 1u << 2,
    CDC_PARAM_CUTOFF_FACTOR = 1u << 3,
    CDC_PARAM_WALL_MIRROR = 1u << 4
};

typedef struct cdc_context cdc_context;
typedef struct cdc_kernels cdc_kernels;

/* ------------------------------------------------------------------ context and mesh */

/* Create a context for one mesh (one MPI rank's part). Checks the mesh (non-empty, positive cell
 * volumes, consistent addressing) and builds cell-face and cell-cell adjacency and spatial bins. */
cdc_status cdc_context_create(const cdc_mesh *mesh, cdc_context **out);
void cdc_context_destroy(cdc_context *ctx);
/* The wall facets the wall-aware kernels mirror across: n faces, each its centre, area vector
 * (pointing out of the mesh) and the centre of its owner cell (3 n doubles each, copied). A context
 * starts with the wall faces of its own mesh; in parallel give every rank those of the whole mesh,
 * so that a kernel crossing a processor boundary mirrors as in a serial run on a curved wall. */
cdc_status cdc_context_set_wall_facets(cdc_context *ctx, int32_t n, const double *centres, const double *areas,
                                       const double *owner_centres);
/* Message of the last error on this context (or of cdc_context_create when ctx is NULL). */
const char *cdc_last_error(const cdc_context *ctx);
/* Message of the last cdc_context_create failure, for the caller that got no context back. */
const char *cdc_create_error(void);
const cdc_mesh *cdc_context_mesh(const cdc_context *ctx);

/* Host cell of one point: walk from hint (or -1), spatial-bin fallback. *cell = -1 if outside. */
cdc_status cdc_locate_point(cdc_context *ctx, const double p[3], int32_t hint, int32_t *cell);

/* ------------------------------------------------------------------ methods */

/* Number of registered kernel methods and their names ("centre", "divided", ...). */
int cdc_method_count(void);
const char *cdc_method_name(int i);
/* The CDC_PARAM_* bits of the parameters method `name` reads (0 for none or an unknown name). */
unsigned cdc_method_params(const char *name);
/* Set the members of prm that method `name` reads and that are 0 to the values it runs with when
 * they are not given (twoGrid search_factor 3, gaussian cutoff_factor 2), so that a caller can say
 * what a run uses, and can tell an explicit 0 (not a valid value there) from a default. */
void cdc_method_fill_defaults(const char *name, cdc_kernel_params *prm);
/* Comma-separated list of method names, for error messages. */
const char *cdc_method_list(void);

/* ------------------------------------------------------------------ kernels */

cdc_status cdc_kernels_create(cdc_context *ctx, const char *method, const cdc_kernel_params *params,
                              cdc_kernels **out);
void cdc_kernels_destroy(cdc_kernels *k);

/* Build the kernels of all particles. Particles outside the mesh get an empty kernel; they are
 * counted and listed (cdc_kernels_outside) and the call returns CDC_ERR_OUTSIDE after building all
 * others, so the caller decides whether that is fatal. Invalid particles (NaN, radius <= 0) stop the
 * call with CDC_ERR_PARTICLE before anything is written. */
cdc_status cdc_kernels_build(cdc_kernels *k, const cdc_particles *p);

/* ---- parallel: kernels that cross processor boundaries (the caller does the communication)
 * 1. each rank sends the particles whose kernel reach (cdc_kernels_reach) touches a neighbour's
 *    mesh to that neighbour, where they are "ghosts";
 * 2. cdc_kernels_build_raw builds un-normalised weights of the local particles and the ghosts over
 *    this rank's cells (a ghost needs no host cell here); cdc_kernels_raw_sums gives each one's sum;
 * 3. the caller adds the sums of every rank (ghost sums go back to the owner) and hands the global
 *    sums, in the same order, to cdc_kernels_normalise; a particle that got no weight anywhere falls
 *    back to its host cell (as in serial). The weights are then those of a serial run: alpha_p,
 *    spreading and gathering over local + ghost particles give the serial result on each rank. */
cdc_status cdc_kernels_build_raw(cdc_kernels *k, const cdc_particles *local, const cdc_particles *ghosts);
const double *cdc_kernels_raw_sums(const cdc_kernels *k);
/* local_ids (may be NULL) name particles in messages */
cdc_status cdc_kernels_normalise(cdc_kernels *k, const double *global_sums, const int64_t *local_ids);
/* How far from its centre a particle of this radius reaches with this method (at least the radius). */
double cdc_kernels_reach(const cdc_kernels *k, double radius);

/* CSR view of the kernels of the last build: particle i has entries offsets[i]..offsets[i+1]-1. */
int32_t cdc_kernels_count(const cdc_kernels *k);
const int32_t *cdc_kernels_offsets(const cdc_kernels *k);
const int32_t *cdc_kernels_cells(const cdc_kernels *k);
const double *cdc_kernels_weights(const cdc_kernels *k);
/* Host cell of each particle of the last build (local particles first; -1: outside this mesh). */
const int32_t *cdc_kernels_hosts(const cdc_kernels *k);
/* Wall time of the last build: locating the particles, and building their kernels. */
void cdc_kernels_timing(const cdc_kernels *k, double *seconds_locate, double *seconds_kernel);
/* Particles found outside the mesh in the last build: count and their ids. */
int32_t cdc_kernels_outside(const cdc_kernels *k, const int64_t **ids);
/* Of this rank's particles of the last build (p as given to it), those whose centre is inside the
 * mesh but that reach partly outside it: an end of one of their three axes, x +- r e_d, lies in no
 * cell and the axis leaves the mesh through a wall or other boundary face (through a processor face
 * it reaches into the neighbour rank's cells: not counted, on either rank, even when it leaves the
 * mesh beyond them, e.g. through a wall close to the processor boundary). *count gets their number,
 * *depth the deepest such end beyond the mesh as a fraction of its particle's radius (found by
 * bisection along the axis, to 1e-6; 0 when none), *id the id of that particle (-1 when none). A
 * particle pressed into a DEM wall reaches beyond it by its contact overlap, so small depths are
 * normal; a large one is a particle leaving the mesh. Six point locations per particle: for reports
 * at write times, not for every coupling. */
cdc_status cdc_kernels_partly_outside(const cdc_kernels *k, const cdc_particles *p, int32_t *count,
                                      double *depth, int64_t *id);

/* alpha_p[c] = sum_i V_i w_ic / V_c with V_i = 4/3 pi r_i^3 (n_cells outputs, overwritten). */
cdc_status cdc_alpha_p(const cdc_kernels *k, const cdc_particles *p, double *alpha_p);
/* Per-particle quantity q_i (ncomp components) spread to cells as density: out[c] = sum_i q_i w_ic / V_c. */
cdc_status cdc_spread(const cdc_kernels *k, const double *q, int ncomp, double *out);
/* Background field at each particle: out_i = sum_c w_ic f_c, the adjoint of cdc_spread (so the
 * momentum a particle gets back equals what it gave). For kernels uniform in volume fraction
 * (w_c = V_c / sum V_c, e.g. bigParticle n = 5) this is eqs. 21-22. Particles outside get 0. */
cdc_status cdc_gather(const cdc_kernels *k, const double *field, int ncomp, double *out);

/* ------------------------------------------------------------------ momentum exchange */

/* The fluid's momentum sources from the particles' forces, spread with the kernels of the last build
 * (local particles, then ghosts, as cdc_spread), per unit fluid mass and cell volume. The fluid's
 * momentum equation gets  -Ksl U + KslUs + f_fluid:
 *   CDC_EXCHANGE_IMPLICIT: Ksl = spread(K / rho), KslUs = spread(K v / rho),
 *                          f_fluid = spread(-(f + K (u_f - u_k)) / rho)   (u_k NULL: the last term is 0)
 *   CDC_EXCHANGE_EXPLICIT: Ksl = KslUs = 0 (may be NULL), f_fluid = spread(-(K (u_f - v) + f) / rho)
 * At a fluid velocity U whose gathered value is u_k (u_f when u_k is NULL), the fluid receives exactly
 * minus sum_i (K_i (u_f,i - v_i) + f_i), what the particles get: Newton's third law for every method. */
typedef enum cdc_exchange_mode { CDC_EXCHANGE_IMPLICIT = 0, CDC_EXCHANGE_EXPLICIT = 1 } cdc_exchange_mode;
typedef struct cdc_exchange_in {
    int32_t n;                /* particles of the last kernel build (local + ghosts) */
    const double *K;          /* n: coefficient of the drag K (u_f - v) on each particle (kg/s) */
    const double *v;          /* 3n: particle velocity */
    const double *u_f;        /* 3n: the fluid velocity the drag used */
    const double *u_k;        /* 3n or NULL: the fluid velocity gathered with these kernels, when u_f came
                                 from other (background) kernels */
    const double *f;          /* 3n or NULL: the particle's other forces that act back on the fluid (N) */
    double rho;               /* fluid density (kg/m3) */
    cdc_exchange_mode mode;
} cdc_exchange_in;
cdc_status cdc_exchange_sources(const cdc_kernels *k, const cdc_exchange_in *in, double *Ksl, double *KslUs,
                                double *f_fluid);

/* ------------------------------------------------------------------ field operations */

/* Diffusion smoothing of a cell field (Zhang et al. 2023 eq. 7): d(phi)/dtau = div(D grad phi), zero flux at every
 * boundary, implicit Euler in pseudo-time to T = b^2/4 in n_steps steps. Conserves sum(phi V) to
 * round-off whatever the linear solver tolerance (flux-form update). D is 1 everywhere, or with
 * d_rule Zhang et al.'s rule D = 0.001 in cells larger than 4 d (d = particle diameter). */
/* The CG tolerance when none is given: it changes the Mueller demo's profiles no more than 1e-12
 * does, in 0.6 times the iterations of 1e-10 (bench/README.md, solver tolerances). */
#define CDC_DIFFUSION_DEFAULT_TOLERANCE 1e-6

typedef struct cdc_diffusion_params {
    double bandwidth;         /* b > 0 (metres) */
    int n_steps;              /* pseudo-time steps (default 4 when 0) */
    double tolerance;         /* relative CG tolerance (CDC_DIFFUSION_DEFAULT_TOLERANCE when 0) */
    int max_iterations;       /* default 1000 when 0 */
    int d_rule;               /* 1: D = 0.001 where cell size > 4 d */
    double particle_diameter; /* d for d_rule */
} cdc_diffusion_params;

cdc_status cdc_diffuse(cdc_context *ctx, const cdc_diffusion_params *prm, double *phi);

/* The same smoothing of n_fields (1 to CDC_DIFFUSE_MAX_FIELDS) cell fields side by side in phi
 * (phi[c n_fields + d]: a vector field's components, or several fields packed): each field gets the
 * bits cdc_diffuse gives it alone, in fewer passes over the mesh (the fields share the matrix). */
#define CDC_DIFFUSE_MAX_FIELDS 8
cdc_status cdc_diffuse_fields(cdc_context *ctx, const cdc_diffusion_params *prm, double *phi, int n_fields);

/* Processor faces of one rank's mesh, for the field operations across ranks. The core has no MPI:
 * the caller (one rank of a decomposed case) lists this rank's processor faces and supplies the halo
 * exchange and the global sum. With a halo set, cdc_diffuse couples the ranks through these faces
 * (same two-point flux as internal faces, CG with global dot products), so the smoothing equals the
 * serial one to the solver tolerance and the total sum(phi V) over all ranks is conserved to
 * round-off; cdc_limit_packing moves excess volume across them as across internal faces. Every rank
 * must call cdc_diffuse (cdc_diffuse_fields with the same n_fields) and cdc_limit_packing the same
 * number of times (the callbacks are collective; cdc_diffuse_fields exchanges once per field). The
 * arrays must outlive the context or the next cdc_context_set_halo. */
typedef struct cdc_halo {
    int32_t n_faces;
    const int32_t *cell;       /* this rank's cell next to each processor face */
    const double *coeff;       /* |S_f| / |C_N - C_P|, C_N the neighbour rank's cell centre; the
                                  same bits on both sides of a face for exact conservation */
    const double *nbr_volume;  /* volume of the neighbour rank's cell (for the D rule) */
    /* nbr[i] = the neighbour rank's value of its cell across face i, given this rank's cell values */
    int (*exchange)(void *user, const double *cell_values, double *nbr);
    /* values[0..n) summed over all ranks, in place, with the same result bits on every rank; each
     * value summed as it would be alone, whatever n (cdc_diffuse_fields then equals cdc_diffuse) */
    int (*sum)(void *user, double *values, int n);
    void *user;                /* passed to the callbacks */
    /* values[0..n) replaced by their maximum over all ranks; may be NULL (then the size-aware
     * diffusion, whose diameter classes start at the smallest diameter of all ranks, refuses) */
    int (*max)(void *user, double *values, int n);
} cdc_halo;

/* Set (or with NULL clear) the halo of a context; returns CDC_ERR_ARGUMENT on inconsistent input. */
cdc_status cdc_context_set_halo(cdc_context *ctx, const cdc_halo *halo);

/* Size-aware diffusion for polydisperse beds: particles are grouped in diameter classes (width
 * class_ratio, e.g. 1.1 = 10 %), each class's PCM field is smoothed with its own bandwidth
 * b_k = bandwidth_over_d * d_k and the classes are summed. Writes alpha_p. p: the particles of the
 * kernels' last build (local, then ghosts). Across ranks (a halo with sum and max) the classes and
 * their mean diameters are those of all ranks' particles, so the result is the serial one. */
cdc_status cdc_alpha_p_diffused_by_size(cdc_context *ctx, const cdc_kernels *k, const cdc_particles *p,
                                        double bandwidth_over_d, double class_ratio,
                                        const cdc_diffusion_params *base, double *alpha_p,
                                        int *n_classes);

/* Packing limiter: where alpha_p exceeds alpha_max, the excess volume moves to face neighbours
 * (volume conserved exactly) until no cell exceeds alpha_max or max_sweeps is reached.
 * Reports the moved volume (m^3) and the number of cells that were over the limit; with a halo,
 * the excess crosses processor faces too and the two reports are this rank's share. */
cdc_status cdc_limit_packing(cdc_context *ctx, double alpha_max, int max_sweeps, double *alpha_p,
                             double *moved_volume, int32_t *n_limited_cells);

/* Exact volume of the intersection of a sphere and an axis-aligned box (to ~1e-12 relative). */
double cdc_sphere_box_volume(const double centre[3], double radius, const double lo[3], const double hi[3]);

#ifdef __cplusplus
}
#endif
#endif
