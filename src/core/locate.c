/*
 * locate.c -- host cell of a point.
 *
 * A walk from a hint cell: at each cell, the face whose plane the point lies furthest beyond
 * (distance along the outward unit normal) is crossed. For convex cells in a convex domain this
 * ends in the host cell, or at a boundary face whose plane the point is beyond (then it is outside).
 * When the walk fails (no hint, a non-convex domain, a hint on another part of the mesh, a loop),
 * candidate cells come from uniform spatial bins of cell bounding boxes, built on first need.
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>

/* Signed distance of p beyond face f's plane, seen from cell c (positive = outside c). */
static inline double beyond(const cdc_context *ctx, int32_t c, int32_t f, const double p[3])
{
    const double *n = ctx->face_unit_normal + 3 * (size_t)f, *C = ctx->mesh->face_centres + 3 * (size_t)f;
    const double s = (p[0] - C[0]) * n[0] + (p[1] - C[1]) * n[1] + (p[2] - C[2]) * n[2];
    return ctx->mesh->owner[f] == c ? s : -s;
}

/* Tolerance for "on the face": a tiny fraction of the cell's size, so points on shared faces
 * belong to some cell and round-off never puts a point outside every cell. */
static double cell_tolerance(const cdc_context *ctx, int32_t c)
{
    const double *bb = ctx->cell_bbox + 6 * (size_t)c;
    return 1e-10 * ((bb[3] - bb[0]) + (bb[4] - bb[1]) + (bb[5] - bb[2]));
}

int cdc_point_in_cell(const cdc_context *ctx, int32_t c, const double p[3])
{
    const double *bb = ctx->cell_bbox + 6 * (size_t)c;
    const double tol = cell_tolerance(ctx, c);
    for (int d = 0; d < 3; ++d)
        if (p[d] < bb[d] - tol || p[d] > bb[3 + d] + tol) return 0;
    for (int32_t q = ctx->cell_face_offsets[c]; q < ctx->cell_face_offsets[c + 1]; ++q)
        if (beyond(ctx, c, ctx->cell_faces[q], p) > tol) return 0;
    return 1;
}

int32_t cdc_exit_face(const cdc_context *ctx, int32_t c, const double p[3])
{
    int32_t best_f = -1;
    double best = cell_tolerance(ctx, c);
    for (int32_t q = ctx->cell_face_offsets[c]; q < ctx->cell_face_offsets[c + 1]; ++q) {
        const int32_t f = ctx->cell_faces[q];
        const double s = beyond(ctx, c, f, p);
        if (s > best) {
            best = s;
            best_f = f;
        }
    }
    return best_f;
}

/* Walk from `start`; returns the host cell, or -1 when the walk cannot decide. */
static int32_t walk(const cdc_context *ctx, int32_t start, const double p[3])
{
    const cdc_mesh *m = ctx->mesh;
    int32_t c = start, prev = -1;
    for (int32_t step = 0; step < ctx->walk_max_steps; ++step) {
        const int32_t best_f = cdc_exit_face(ctx, c, p);
        if (best_f < 0) return c;
        /* Beyond a boundary face: outside if the domain is convex; the bins decide otherwise. */
        if (best_f >= m->n_internal_faces) return -1;
        const int32_t next = m->owner[best_f] == c ? m->neighbour[best_f] : m->owner[best_f];
        if (next == prev) return -1; /* oscillation between two cells: let the bins decide */
        prev = c;
        c = next;
    }
    return -1;
}

static cdc_status build_bins(cdc_context *ctx)
{
    const cdc_mesh *m = ctx->mesh;
    const double span[3] = {ctx->mesh_hi[0] - ctx->mesh_lo[0], ctx->mesh_hi[1] - ctx->mesh_lo[1],
                            ctx->mesh_hi[2] - ctx->mesh_lo[2]};
    /* About one cell per bin: bin edge = mean cell edge. */
    const double h = cbrt(ctx->total_volume / m->n_cells);
    size_t total = 1;
    for (int d = 0; d < 3; ++d) {
        double nb = ceil(span[d] / h * (1.0 - 1e-12)); /* 120 cells of size h: 120 bins, not 121 */
        if (nb < 1) nb = 1;
        if (nb > 1024) nb = 1024;
        ctx->nbin[d] = (int32_t)nb;
        ctx->bin_lo[d] = ctx->mesh_lo[d];
        ctx->bin_size[d] = span[d] > 0 ? span[d] / nb : 1.0;
        total *= (size_t)nb;
    }
    ctx->bin_offsets = calloc(total + 1, sizeof(int32_t));
    if (!ctx->bin_offsets) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for location bins");
    for (int pass = 0; pass < 2; ++pass) {
        int32_t *fill = NULL;
        if (pass == 1) {
            for (size_t b = 0; b < total; ++b) ctx->bin_offsets[b + 1] += ctx->bin_offsets[b];
            ctx->bin_cells = malloc((size_t)ctx->bin_offsets[total] * sizeof(int32_t));
            fill = calloc(total, sizeof(int32_t));
            if (!ctx->bin_cells || !fill) {
                free(fill);
                return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for location bins");
            }
        }
        for (int32_t c = 0; c < m->n_cells; ++c) {
            const double *bb = ctx->cell_bbox + 6 * (size_t)c;
            int32_t lo[3], hi[3];
            for (int d = 0; d < 3; ++d) {
                /* A box edge that falls on a bin edge (box meshes with one cell per bin) must not
                 * register the cell in the next bin too: shrink the box by a hair first. Points
                 * within the tolerance of a face are still found: the walk or a neighbour bin
                 * holds the cell that shares the face. */
                const double eps = 1e-9 * ctx->bin_size[d];
                lo[d] = (int32_t)floor((bb[d] + eps - ctx->bin_lo[d]) / ctx->bin_size[d]);
                hi[d] = (int32_t)floor((bb[3 + d] - eps - ctx->bin_lo[d]) / ctx->bin_size[d]);
                if (lo[d] < 0) lo[d] = 0;
                if (hi[d] >= ctx->nbin[d]) hi[d] = ctx->nbin[d] - 1;
            }
            for (int32_t i = lo[0]; i <= hi[0]; ++i)
                for (int32_t j = lo[1]; j <= hi[1]; ++j)
                    for (int32_t k = lo[2]; k <= hi[2]; ++k) {
                        const size_t b = ((size_t)k * ctx->nbin[1] + j) * ctx->nbin[0] + i;
                        if (pass == 0)
                            ctx->bin_offsets[b + 1]++;
                        else
                            ctx->bin_cells[ctx->bin_offsets[b] + fill[b]++] = c;
                    }
        }
        free(fill);
    }
    ctx->bins_built = 1;
    return CDC_OK;
}

static int32_t search_bins(const cdc_context *ctx, const double p[3])
{
    int32_t ijk[3];
    for (int d = 0; d < 3; ++d) {
        ijk[d] = (int32_t)floor((p[d] - ctx->bin_lo[d]) / ctx->bin_size[d]);
        if (ijk[d] == ctx->nbin[d]) ijk[d]--; /* a point on the upper edge of the mesh */
        if (ijk[d] < 0 || ijk[d] >= ctx->nbin[d]) return -1;
    }
    const size_t b = ((size_t)ijk[2] * ctx->nbin[1] + ijk[1]) * ctx->nbin[0] + ijk[0];
    for (int32_t q = ctx->bin_offsets[b]; q < ctx->bin_offsets[b + 1]; ++q)
        if (cdc_point_in_cell(ctx, ctx->bin_cells[q], p)) return ctx->bin_cells[q];
    return -1;
}

cdc_status cdc_locate_point(cdc_context *ctx, const double p[3], int32_t hint, int32_t *cell)
{
    if (!ctx || !p || !cell) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_locate_point: NULL argument");
    if (!isfinite(p[0]) || !isfinite(p[1]) || !isfinite(p[2]))
        return cdc_fail(ctx, CDC_ERR_PARTICLE, "cdc_locate_point: point (%g %g %g) is not finite", p[0],
                        p[1], p[2]);
    const int32_t nc = ctx->mesh->n_cells;
    for (int d = 0; d < 3; ++d)
        if (p[d] < ctx->mesh_lo[d] - 1e-10 * (ctx->mesh_hi[d] - ctx->mesh_lo[d]) ||
            p[d] > ctx->mesh_hi[d] + 1e-10 * (ctx->mesh_hi[d] - ctx->mesh_lo[d])) {
            *cell = -1;
            return CDC_OK;
        }
    int32_t c = (hint >= 0 && hint < nc) ? walk(ctx, hint, p) : -1;
    if (c < 0) {
        if (!ctx->bins_built) {
            cdc_status st = build_bins(ctx);
            if (st != CDC_OK) return st;
        }
        c = search_bins(ctx, p);
    }
    *cell = c;
    return CDC_OK;
}

/* The range of bins within s of x along each axis (s_d = s plus a few of the hairs build_bins shrinks
 * boxes by, so a box that reaches x - s is in); 0 when that box misses the grid. */
static int bin_range(const cdc_context *ctx, const double x[3], double s, int32_t lo[3], int32_t hi[3])
{
    for (int d = 0; d < 3; ++d) {
        const double sd = s + 4e-9 * ctx->bin_size[d];
        lo[d] = (int32_t)floor((x[d] - sd - ctx->bin_lo[d]) / ctx->bin_size[d]);
        hi[d] = (int32_t)floor((x[d] + sd - ctx->bin_lo[d]) / ctx->bin_size[d]);
        if (lo[d] < 0) lo[d] = 0;
        if (hi[d] >= ctx->nbin[d]) hi[d] = ctx->nbin[d] - 1;
        if (lo[d] > hi[d]) return 0;
    }
    return 1;
}

/* The cells of the bins lo..hi nearer to x than *best (squared distance to their bounding boxes), or
 * as near with a smaller index: *best and *cell updated. */
static void nearest_in_bins(const cdc_context *ctx, const double x[3], const int32_t lo[3], const int32_t hi[3],
                            double *best, int32_t *cell)
{
    for (int32_t k = lo[2]; k <= hi[2]; ++k)
        for (int32_t j = lo[1]; j <= hi[1]; ++j)
            for (int32_t i = lo[0]; i <= hi[0]; ++i) {
                const size_t b = ((size_t)k * ctx->nbin[1] + j) * ctx->nbin[0] + i;
                for (int32_t q = ctx->bin_offsets[b]; q < ctx->bin_offsets[b + 1]; ++q) {
                    const int32_t c = ctx->bin_cells[q];
                    const double d2 = cdc_box_dist2(ctx->cell_bbox + 6 * (size_t)c, x);
                    if (d2 < *best || (d2 == *best && (*cell < 0 || c < *cell))) {
                        *best = d2;
                        *cell = c;
                    }
                }
            }
}

cdc_status cdc_nearest_cell(cdc_context *ctx, const double x[3], double reach, int32_t *cell)
{
    *cell = -1;
    if (!ctx->bins_built) {
        cdc_status st = build_bins(ctx);
        if (st != CDC_OK) return st;
    }
    int32_t lo[3], hi[3];
    if (!bin_range(ctx, x, reach, lo, hi)) return CDC_OK; /* the sphere misses this mesh's box */
    /* A first guess from the bin of the range nearest to x (a ghost just across a processor boundary:
     * the cells on this side of it): the distance it gives bounds the search, so the scan covers the
     * bins within that distance instead of the whole reach (the ghosts' search was most of the locate
     * stage on 2 ranks). Any cell nearer than the guess lies in those bins, and ties go to the smaller
     * index, so the answer is the cell a scan of the whole reach gives. */
    int32_t g[3];
    for (int d = 0; d < 3; ++d) {
        const int32_t b = (int32_t)floor((x[d] - ctx->bin_lo[d]) / ctx->bin_size[d]);
        g[d] = b < lo[d] ? lo[d] : (b > hi[d] ? hi[d] : b);
    }
    double best = reach * reach;
    nearest_in_bins(ctx, x, g, g, &best, cell);
    if (*cell >= 0 && !bin_range(ctx, x, sqrt(best) * (1.0 + 1e-12), lo, hi)) return CDC_OK;
    nearest_in_bins(ctx, x, lo, hi, &best, cell);
    return CDC_OK;
}
