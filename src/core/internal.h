/*
 * internal.h -- private structures of the core, shared by its source files. Not installed.
 */
#ifndef CDC_INTERNAL_H
#define CDC_INTERNAL_H

#include "coarse_dem.h"

#include <stdarg.h>

#define CDC_MSG_LEN 1024
#define CDC_PI 3.14159265358979323846

/* A growable array of int32 or double, reused across steps (capacity only grows). */
typedef struct { int32_t *v; size_t n, cap; } cdc_ivec;
typedef struct { double *v; size_t n, cap; } cdc_dvec;

int cdc_ivec_reserve(cdc_ivec *a, size_t cap);
int cdc_dvec_reserve(cdc_dvec *a, size_t cap);

/* Append x; -1 when out of memory. Inline: the kernel builds push every cell they visit, and an
 * out-of-line call per cell was 11 % of a gaussian build (perf, bench -m gaussian_b3d). */
static inline int cdc_ivec_push(cdc_ivec *a, int32_t x)
{
    if (a->n == a->cap && cdc_ivec_reserve(a, a->n + 1)) return -1;
    a->v[a->n++] = x;
    return 0;
}

static inline int cdc_dvec_push(cdc_dvec *a, double x)
{
    if (a->n == a->cap && cdc_dvec_reserve(a, a->n + 1)) return -1;
    a->v[a->n++] = x;
    return 0;
}
void cdc_ivec_free(cdc_ivec *a);
void cdc_dvec_free(cdc_dvec *a);

/* A wall plane near a particle: points x with dot(x - origin, normal) = 0; normal points out. */
typedef struct { double origin[3]; double normal[3]; } cdc_plane;
/* A wall face for mirroring: its plane and the centre of the cell that owns it (wall_facets.c). */
typedef struct { cdc_plane plane; double owner[3]; } cdc_facet;

/* Signed distance of x from the plane, positive on the side its normal points to (outside). */
static inline double cdc_plane_offset(const cdc_plane *p, const double x[3])
{
    return (x[0] - p->origin[0]) * p->normal[0] + (x[1] - p->origin[1]) * p->normal[1] +
           (x[2] - p->origin[2]) * p->normal[2];
}
#define CDC_MAX_WALL_FACETS 64 /* distinct wall-face planes within a kernel's reach (a faceted curved
                                  * wall gives one per facet); more is an error */
#define CDC_MAX_PLANES 6   /* mirror planes kept from those facets: at most the walls of a box */
/* Facets whose normals are closer than this (cosine of 60 degrees) belong to one wall surface, which
 * is mirrored across its nearest facet only; walls meeting at a sharper angle (box edges, the
 * corner of a column's wall with its bottom) are mirrored across each. */
#define CDC_SAME_WALL_COS 0.5
#define CDC_MAX_IMAGES 64  /* mirror images of one particle (a box corner in a thin slab has ~8) */
#define CDC_N_SCRATCH 8
/* Relative slack on "within radius" tests: on regular lattices cell centres sit exactly on a
 * kernel's radius, and round-off must not decide (asymmetrically) whether they are in. */
#define CDC_RADIUS_SLACK (1.0 + 1e-10)

struct cdc_context {
    const cdc_mesh *mesh;
    char msg[CDC_MSG_LEN];

    /* cell -> faces (CSR), built once */
    int32_t *cell_face_offsets;
    int32_t *cell_faces;
    /* cell -> neighbouring cells across internal faces (CSR), built once */
    int32_t *cell_cell_offsets;
    int32_t *cell_cells;
    /* per cell: axis-aligned bounding box (lo xyz, hi xyz) and whether the cell IS that box */
    double *cell_bbox;
    /* per cell: centre x, y, z and volume side by side, for the loops over a kernel's cells (the
     * candidate filter, the radial weights): one cache line per cell instead of a miss in each of the
     * mesh's two arrays (the volume's load was a sixth of a Gaussian kernel build) */
    double *cell_xv;
    uint8_t *cell_is_box;
    /* per face: unit normal (along the face area vector), for the point-location walk */
    double *face_unit_normal;
    int32_t walk_max_steps; /* cells a location walk may cross before the bins decide */
    double mesh_lo[3], mesh_hi[3];
    double total_volume;

    /* wall facets for mirroring (wall_facets.c), binned by owner centre */
    int32_t n_facets;
    cdc_facet *facets;
    double facet_lo[3], facet_bin;
    int32_t facet_nbin[3];
    int32_t *facet_offsets, *facet_items;
    int32_t *facet_plane;     /* per facet: its plane's number (a run of coplanar facets in facet order
                               * shares one), so a query skips the faces of a plane it has taken */

    /* spatial bins for the location fallback, built on first need */
    int bins_built;
    int32_t nbin[3];
    double bin_lo[3], bin_size[3];
    int32_t *bin_offsets;
    int32_t *bin_cells;

    /* scratch for neighbourhood searches: visit stamps avoid clearing a n_cells array per particle */
    int32_t *stamp;
    int32_t stamp_now;
    cdc_ivec queue;
    cdc_ivec near_cells;   /* method scratch: the cells of one neighbourhood */

    /* field operations: geometric face coefficients |S_f|/|d_f| of internal faces (lazy) and
     * scratch vectors reused across calls */
    double *face_coeff;
    cdc_dvec scratch[CDC_N_SCRATCH];
    cdc_dvec class_q, class_field, class_sum; /* size-aware smoothing */

    /* processor faces and the caller's exchange (parallel diffusion); has_halo 0: serial */
    int has_halo;
    cdc_halo halo;
    cdc_dvec halo_coeff, halo_nbr;
    cdc_dvec halo_fields;  /* diffusion of several fields: one field's cell values, then its nbr values */
    cdc_dvec halo_work;    /* packing limiter: the other side's values per processor face */
};

/* Set the context's message (printf style); returns status for one-line error returns. */
cdc_status cdc_fail(cdc_context *ctx, cdc_status st, const char *fmt, ...);

/* Is p inside convex cell c (with a tolerance relative to the cell size)? */
int cdc_point_in_cell(const cdc_context *ctx, int32_t c, const double p[3]);

/* The face of cell c whose plane p lies furthest beyond (by more than the cell's tolerance), or -1
 * when p is inside c: the face a straight path from inside c to p leaves c through. */
int32_t cdc_exit_face(const cdc_context *ctx, int32_t c, const double p[3]);

/* New visit generation for the stamp array (wraps safely). */
int32_t cdc_next_stamp(cdc_context *ctx);

/* One particle's kernel under construction: the method appends (cell, raw weight >= 0);
 * the driver normalises the raw weights to sum 1. */
typedef struct cdc_kernel_builder {
    cdc_ivec *cells;
    cdc_dvec *weights;
    int32_t fallback_cell; /* set by a method: the cell that takes the particle if no other does */
    int distinct;          /* set by a method: no cell appended twice (the driver skips merging) */
    struct cdc_candidates *search; /* the kernel set's candidate lists, for cdc_cells_within */
} cdc_kernel_builder;

int cdc_kernel_add(cdc_kernel_builder *b, int32_t cell, double w);

/* What a method gets for one particle. */
typedef struct cdc_particle_in {
    double x[3];
    double r;
    int32_t host;   /* host cell of the centre; for a ghost, a local cell to start searches from */
    int ghost;      /* 1: the particle belongs to another rank, its centre is not in this mesh */
} cdc_particle_in;

/*
 * One kernel method = one file = one of these, registered in methods.c.
 * check():  validate parameters; return CDC_ERR_ARGUMENT with a message naming the parameter.
 * reach():  radius beyond which the kernel of a particle of radius r never reaches (for the
 *           "kernel bigger than the mesh" check).
 * build():  append raw weights of one particle.
 */
typedef struct cdc_method {
    const char *name;
    unsigned params; /* CDC_PARAM_* bits: the members of cdc_kernel_params it reads */
    cdc_status (*check)(cdc_context *ctx, const cdc_kernel_params *prm);
    double (*reach)(const cdc_kernel_params *prm, double r);
    cdc_status (*build)(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out);
    /* optional: set the members it reads that are left 0 to the method's defaults */
    void (*defaults)(cdc_kernel_params *prm);
} cdc_method;

const cdc_method *cdc_find_method(const char *name);

/* Cells whose centre lies within `radius` of x, found by flood fill from the start cell across
 * faces. The start cell is included too (the host of a particle), unless seed_only (a ghost's
 * start cell, included only if it qualifies). */
cdc_status cdc_flood_within(cdc_context *ctx, const double x[3], int32_t start, int seed_only, double radius,
                            cdc_ivec *cells);

/* Per-cell candidate lists of a kernel set for its largest search radius (candidates.c). The driver
 * sets `wanted` to the largest radius of a build; the lists are made on the first search that needs
 * them. Lists beyond CDC_CANDIDATE_CAP entries in all are not made (the flood fill serves). */
typedef struct cdc_candidates {
    double radius;     /* radius the lists serve; 0: none made */
    double wanted;     /* largest search radius of the current build */
    double too_large;  /* a radius whose lists would exceed the cap (0: none found yet) */
    int32_t *offsets, *cells;
} cdc_candidates;
#define CDC_CANDIDATE_CAP ((size_t)1 << 26) /* entries: 256 MB of int32 */
void cdc_candidates_free(cdc_candidates *cand);

/* The same cells as cdc_flood_within (see candidates.c for the one difference on distorted cells),
 * by filtering the start cell's candidate list when x lies in the start cell's sphere and cand
 * serves the radius; by flood fill otherwise (cand may be NULL). */
cdc_status cdc_cells_within(cdc_context *ctx, cdc_candidates *cand, const double x[3], int32_t start,
                            int seed_only, double radius, cdc_ivec *cells);

/* The context's wall facets from its own mesh's wall faces (at creation; wall_facets.c). */
cdc_status cdc_wall_facets_from_mesh(cdc_context *ctx);

/* The planes of the wall facets within `radius` of x (owner cell centre within it, plane closer
 * than it), deduplicated (a flat wall's faces are one plane), into planes[] (room for
 * CDC_MAX_WALL_FACETS; more is CDC_ERR_UNSUPPORTED). cdc_nearest_wall_planes() then keeps the
 * mirror planes among them. */
cdc_status cdc_wall_planes_near(cdc_context *ctx, const double x[3], double radius, cdc_plane *planes,
                                int *n_planes);

/* Cells whose bounding box overlaps the sphere (x, radius), by flood fill from the start cell. */
cdc_status cdc_cells_overlapping(cdc_context *ctx, const double x[3], int32_t start, int seed_only,
                                 double radius, cdc_ivec *cells);

/* The local cell whose bounding box is nearest to x, if within `reach` (else -1; of equally near
 * cells the smallest index): where the searches for a ghost particle start. */
cdc_status cdc_nearest_cell(cdc_context *ctx, const double x[3], double reach, int32_t *cell);

/* The mirror planes among the wall facets near x, in place: nearest first, a facet is kept unless
 * its normal is within 60 degrees (CDC_SAME_WALL_COS) of a kept one's, i.e. each wall surface is
 * mirrored across the facet nearest to x only: a faceted curved wall (a cylinder on an O-grid) acts
 * as its tangent plane there, a box keeps all its planes. Ties in distance are broken by the
 * normal's components, so the result does not depend on the order the facets were found in.
 * Returns CDC_MAX_PLANES + 1 if more would be kept (a wall with more than six sharp corners
 * within reach), else the count kept. */
int cdc_nearest_wall_planes(const double x[3], cdc_plane *planes, int n_planes);

/* Images of x across the wall planes (method of images), x itself first: every point reached by
 * reflecting x or an image across a plane, kept while it lies less than `reach` beyond every plane
 * (farther images cannot touch a cell inside). Independent of the planes' order, so a symmetric
 * particle set gives a symmetric field. Returns the count, or -1 above CDC_MAX_IMAGES. */
int cdc_mirror_images(const double x[3], const cdc_plane *planes, int n_planes, double reach,
                      double images[][3]);

static inline double cdc_dist2(const double a[3], const double b[3])
{
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

/* Squared distance from x to the box bb = {lo[3], hi[3]} (a cell's bounding box); 0 inside. */
static inline double cdc_box_dist2(const double bb[6], const double x[3])
{
    double d2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        const double e = x[d] < bb[d] ? bb[d] - x[d] : (x[d] > bb[3 + d] ? x[d] - bb[3 + d] : 0.0);
        d2 += e * e;
    }
    return d2;
}

/* The id of particle i in messages: its DEM id, or its index. */
static inline int64_t cdc_particle_id(const cdc_particles *p, int32_t i) { return p->id ? p->id[i] : (int64_t)i; }

/* A kernel set: the CSR kernels of the last build and the buffers reused across builds (kernels.c
 * builds them, kernel_use.c uses them). */
struct cdc_kernels {
    cdc_context *ctx;
    const cdc_method *method;
    cdc_kernel_params prm;
    int32_t n;                 /* particles of the last build (local, then ghosts) */
    int32_t n_local;           /* of which this rank's own */
    cdc_dvec raw_sums;         /* per particle: sum of raw weights on this rank (parallel builds) */
    cdc_ivec fallback_pos;     /* per particle: entry of its fallback cell, or -1 (parallel builds) */
    cdc_ivec offsets, cells;   /* CSR result */
    cdc_dvec weights;
    cdc_ivec raw_cells;        /* one particle's raw entries, before merging */
    cdc_dvec raw_weights;
    int32_t *slot;             /* cell -> position in the current particle's merged list */
    int32_t *slot_stamp;
    int32_t slot_now;
    cdc_ivec hosts;            /* host cell of each particle in the last build */
    cdc_candidates cand;       /* per-cell candidate lists of the radius searches (candidates.c) */
    double seconds_locate, seconds_kernel; /* wall time of the last build's two passes */
    int64_t *outside_ids;      /* ids of the particles outside the mesh in the last build */
    int32_t n_outside;
    size_t outside_cap;
};

/* The context a kernel set was created with (exchange.c spreads with it). */
cdc_context *cdc_kernels_context(const cdc_kernels *k);

#endif
