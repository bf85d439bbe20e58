/*
 * wall_facets.c -- the wall faces that the wall-aware kernels mirror across, found by position.
 *
 * A facet is a wall face's plane (centre, outward unit normal) and the centre of the cell that owns
 * it. A kernel of radius R around x takes the facets whose owner's centre lies within R of x (the
 * cells such a kernel covers) and whose plane is closer than R; cdc_nearest_wall_planes then keeps
 * the mirror planes among them. The facets are this rank's own wall faces unless the caller gives
 * the context those of the whole mesh (cdc_context_set_wall_facets): then a kernel crossing a
 * processor boundary mirrors across the same facets on every rank, as in a serial run, also when
 * the facet nearest to it lies in another rank's part of a curved wall.
 *
 * The facets are found through a uniform grid over their owners' centres, with bins of about two
 * wall cells, so a query costs the few bins around the kernel, not a pass over the wall.
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int32_t bin_of(const cdc_context *ctx, int d, double v)
{
    const double s = (v - ctx->facet_lo[d]) / ctx->facet_bin;
    const int32_t b = s < 0 ? 0 : (int32_t)s;
    return b >= ctx->facet_nbin[d] ? ctx->facet_nbin[d] - 1 : b;
}

static size_t bin_index(const cdc_context *ctx, int32_t i, int32_t j, int32_t k)
{
    return ((size_t)k * (size_t)ctx->facet_nbin[1] + (size_t)j) * (size_t)ctx->facet_nbin[0] + (size_t)i;
}

/* Take n facets (copied) and bin them. */
static cdc_status store_facets(cdc_context *ctx, int32_t n, const double *centres, const double *areas,
                               const double *owners)
{
    free(ctx->facets);
    free(ctx->facet_offsets);
    free(ctx->facet_items);
    free(ctx->facet_plane);
    ctx->facets = NULL;
    ctx->facet_offsets = ctx->facet_items = ctx->facet_plane = NULL;
    ctx->n_facets = 0;
    if (n <= 0) return CDC_OK;

    ctx->facets = malloc((size_t)n * sizeof *ctx->facets);
    if (!ctx->facets) return cdc_fail(ctx, CDC_ERR_NOMEM, "wall facets: out of memory");
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, gap = 0.0;
    for (int32_t f = 0; f < n; ++f) {
        cdc_facet *q = ctx->facets + f;
        const double *S = areas + 3 * (size_t)f;
        const double mag = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
        if (!(mag > 0.0)) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "wall facets: facet %d has no area", (int)f);
        for (int d = 0; d < 3; ++d) {
            q->plane.origin[d] = centres[3 * (size_t)f + d];
            q->plane.normal[d] = S[d] / mag;
            q->owner[d] = owners[3 * (size_t)f + d];
            lo[d] = fmin(lo[d], q->owner[d]);
            hi[d] = fmax(hi[d], q->owner[d]);
        }
        gap += sqrt(cdc_dist2(q->plane.origin, q->owner));
    }
    /* bins of about two wall cells (the owner is half a cell from its face), fewer if that would
     * make more bins than a few per facet */
    double h = 4.0 * gap / n;
    for (;;) {
        size_t total = 1;
        for (int d = 0; d < 3; ++d) {
            ctx->facet_nbin[d] = (int32_t)fmin(1024.0, floor((hi[d] - lo[d]) / h) + 1.0);
            total *= (size_t)ctx->facet_nbin[d];
        }
        if (total <= 4 * (size_t)n + 64) break;
        h *= 1.5;
    }
    ctx->facet_bin = h;
    for (int d = 0; d < 3; ++d) ctx->facet_lo[d] = lo[d];
    const size_t nb = (size_t)ctx->facet_nbin[0] * (size_t)ctx->facet_nbin[1] * (size_t)ctx->facet_nbin[2];
    ctx->facet_offsets = calloc(nb + 1, sizeof(int32_t));
    ctx->facet_items = malloc((size_t)n * sizeof(int32_t));
    ctx->facet_plane = malloc((size_t)n * sizeof(int32_t));
    if (!ctx->facet_offsets || !ctx->facet_items || !ctx->facet_plane)
        return cdc_fail(ctx, CDC_ERR_NOMEM, "wall facets: out of memory");
    size_t *bin = malloc((size_t)n * sizeof *bin);
    if (!bin) return cdc_fail(ctx, CDC_ERR_NOMEM, "wall facets: out of memory");
    for (int32_t f = 0; f < n; ++f) {
        const double *o = ctx->facets[f].owner;
        bin[f] = bin_index(ctx, bin_of(ctx, 0, o[0]), bin_of(ctx, 1, o[1]), bin_of(ctx, 2, o[2]));
        ++ctx->facet_offsets[bin[f] + 1];
    }
    for (size_t b = 0; b < nb; ++b) ctx->facet_offsets[b + 1] += ctx->facet_offsets[b];
    for (int32_t f = 0; f < n; ++f) ctx->facet_items[ctx->facet_offsets[bin[f]]++] = f; /* by facet index */
    for (size_t b = nb; b > 0; --b) ctx->facet_offsets[b] = ctx->facet_offsets[b - 1];
    ctx->facet_offsets[0] = 0;
    free(bin);
    /* Plane numbers: a facet with the same normal (to the bit) as the first facet of the previous
     * facet's run, its centre within 1e-12 of a bin of that facet's plane, continues the run; a flat
     * wall met again later gets a new number, which costs a query only the skip, not a plane. Two
     * facets of one run are then within 2e-12 h of each other's plane: one plane for a query of
     * radius 2e-3 h or more (cdc_wall_planes_near's 1e-9 of the radius), which then tests each
     * plane's faces until one is taken and skips the rest. */
    for (int32_t f = 0, first = 0, number = 0; f < n; ++f) {
        const cdc_plane *a = &ctx->facets[first].plane, *c = &ctx->facets[f].plane;
        const int same_normal = a->normal[0] == c->normal[0] && a->normal[1] == c->normal[1] && a->normal[2] == c->normal[2];
        if (f > 0 && !(same_normal && fabs(cdc_plane_offset(a, c->origin)) <= 1e-12 * h)) {
            first = f;
            ++number;
        }
        ctx->facet_plane[f] = number;
    }
    ctx->n_facets = n; /* only now: a query never meets a half-made set after an allocation failed */
    return CDC_OK;
}

cdc_status cdc_wall_facets_from_mesh(cdc_context *ctx)
{
    const cdc_mesh *m = ctx->mesh;
    const int32_t nb = m->n_faces - m->n_internal_faces;
    int32_t n = 0;
    for (int32_t b = 0; b < nb; ++b) n += m->boundary_face_kind[b] == CDC_FACE_WALL;
    double *buf = malloc(9 * (size_t)(n > 0 ? n : 1) * sizeof(double));
    if (!buf) return cdc_fail(ctx, CDC_ERR_NOMEM, "wall facets: out of memory");
    int32_t k = 0;
    for (int32_t b = 0; b < nb; ++b) {
        if (m->boundary_face_kind[b] != CDC_FACE_WALL) continue;
        const int32_t f = m->n_internal_faces + b;
        memcpy(buf + 3 * (size_t)k, m->face_centres + 3 * (size_t)f, 3 * sizeof(double));
        memcpy(buf + 3 * (size_t)(n + k), m->face_areas + 3 * (size_t)f, 3 * sizeof(double));
        memcpy(buf + 3 * (size_t)(2 * n + k), m->cell_centres + 3 * (size_t)m->owner[f], 3 * sizeof(double));
        ++k;
    }
    const cdc_status st = store_facets(ctx, n, buf, buf + 3 * (size_t)n, buf + 6 * (size_t)n);
    free(buf);
    return st;
}

cdc_status cdc_context_set_wall_facets(cdc_context *ctx, int32_t n, const double *centres, const double *areas,
                                       const double *owner_centres)
{
    if (!ctx) return CDC_ERR_ARGUMENT;
    if (n < 0 || (n > 0 && (!centres || !areas || !owner_centres)))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_context_set_wall_facets: %d facets without their data", (int)n);
    return store_facets(ctx, n, centres, areas, owner_centres);
}

cdc_status cdc_wall_planes_near(cdc_context *ctx, const double x[3], double radius, cdc_plane *planes,
                                int *n_planes)
{
    *n_planes = 0;
    if (ctx->n_facets == 0) return CDC_OK;
    int32_t b0[3], b1[3];
    for (int d = 0; d < 3; ++d) {
        b0[d] = bin_of(ctx, d, x[d] - radius);
        b1[d] = bin_of(ctx, d, x[d] + radius);
    }
    const double r2 = radius * radius * CDC_RADIUS_SLACK;
    int32_t known_numbers[CDC_MAX_WALL_FACETS]; /* the plane numbers of the planes taken */
    int n_known = 0;
    const int skip_by_number = radius >= 2e-3 * ctx->facet_bin; /* see store_facets; else every face is tested */
    for (int32_t k = b0[2]; k <= b1[2]; ++k)
        for (int32_t j = b0[1]; j <= b1[1]; ++j)
            for (int32_t i = b0[0]; i <= b1[0]; ++i) {
                const size_t b = bin_index(ctx, i, j, k);
                for (int32_t q = ctx->facet_offsets[b]; q < ctx->facet_offsets[b + 1]; ++q) {
                    /* a face of a plane taken already changes nothing, whatever its owner's distance */
                    const int32_t number = ctx->facet_plane[ctx->facet_items[q]];
                    int taken = 0;
                    for (int p = 0; p < n_known && !taken; ++p) taken = known_numbers[p] == number;
                    if (taken) continue;
                    const cdc_facet *fc = ctx->facets + ctx->facet_items[q];
                    if (cdc_dist2(fc->owner, x) > r2 || -cdc_plane_offset(&fc->plane, x) >= radius) continue;
                    int known = 0; /* the same plane as one already taken (a flat wall's faces) */
                    for (int p = 0; p < *n_planes && !known; ++p) {
                        const cdc_plane *o = planes + p;
                        const double dn = fc->plane.normal[0] * o->normal[0] + fc->plane.normal[1] * o->normal[1] +
                                          fc->plane.normal[2] * o->normal[2];
                        known = dn > 1.0 - 1e-9 && fabs(cdc_plane_offset(o, fc->plane.origin)) <= 1e-9 * radius;
                    }
                    if (known) continue;
                    if (*n_planes >= CDC_MAX_WALL_FACETS)
                        return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                                        "wallMirror: more than %d distinct wall-face planes within %g m of (%g %g %g) "
                                        "(a wall more finely faceted than the kernel can mirror: a larger mesh cell "
                                        "at the wall, a smaller kernel, or wallMirror false)",
                                        CDC_MAX_WALL_FACETS, radius, x[0], x[1], x[2]);
                    if (skip_by_number) known_numbers[n_known++] = number; /* one per plane: room enough */
                    planes[(*n_planes)++] = fc->plane;
                }
            }
    return CDC_OK;
}
