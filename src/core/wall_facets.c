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
 * wall cells, so a query costs the few bins around the kernel, not a pass over the wall. A kernel
 * set with candidate lists (candidates.c) also gets a facet list per cell, the facets of those bins
 * that a kernel about a point of the cell can take, in the same order: the same planes for a
 * tenth of the facets looked at (the bins' box around a sphere holds several times its facets).
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
    if (++ctx->facets_version == 0) ctx->facets_version = 1; /* 0 means "no lists" in the candidates */
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

/* One facet of a query: its plane joins planes[] when the facet is within the radius of x and the
 * plane is not one taken already (by number, or the same plane under another number). The numbers
 * skipped: the planes taken and those x is too far inside of (a query then looks at one face of a
 * far wall, not at all the faces of it in reach). */
typedef struct {
    const double *x;
    double radius, r2;
    int skip_by_number; /* see store_facets; else every face is tested */
    int32_t known_numbers[CDC_MAX_WALL_FACETS]; /* plane numbers whose faces change nothing more */
    int n_known;
} facet_query;

static inline cdc_status consider(cdc_context *ctx, facet_query *fq, int32_t f, int32_t number, cdc_plane *planes,
                                  int *n_planes)
{
    /* a face of a plane taken already changes nothing, whatever its owner's distance */
    int taken = 0;
    for (int p = 0; p < fq->n_known; ++p) taken |= fq->known_numbers[p] == number;
    if (taken) return CDC_OK;
    const cdc_facet *fc = ctx->facets + f;
    const double *x = fq->x, radius = fq->radius, inside = -cdc_plane_offset(&fc->plane, x);
    if (inside >= radius) {
        /* x is beyond this facet's plane's reach, and so beyond every face of its run's: they lie
         * within 2e-12 h of each other's plane (store_facets), so none of them can be taken */
        if (inside >= radius + 4e-12 * ctx->facet_bin && fq->n_known < CDC_MAX_WALL_FACETS)
            fq->known_numbers[fq->n_known++] = number;
        return CDC_OK;
    }
    if (cdc_dist2(fc->owner, x) > fq->r2) return CDC_OK;
    for (int p = 0; p < *n_planes; ++p) { /* the same plane as one already taken (a flat wall's faces) */
        const cdc_plane *o = planes + p;
        const double dn = fc->plane.normal[0] * o->normal[0] + fc->plane.normal[1] * o->normal[1] +
                          fc->plane.normal[2] * o->normal[2];
        if (dn > 1.0 - 1e-9 && fabs(cdc_plane_offset(o, fc->plane.origin)) <= 1e-9 * radius) return CDC_OK;
    }
    if (*n_planes >= CDC_MAX_WALL_FACETS)
        return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                        "wallMirror: more than %d distinct wall-face planes within %g m of (%g %g %g) "
                        "(a wall more finely faceted than the kernel can mirror: a larger mesh cell "
                        "at the wall, a smaller kernel, or wallMirror false)",
                        CDC_MAX_WALL_FACETS, radius, x[0], x[1], x[2]);
    if (fq->skip_by_number && fq->n_known < CDC_MAX_WALL_FACETS) fq->known_numbers[fq->n_known++] = number;
    planes[(*n_planes)++] = fc->plane;
    return CDC_OK;
}

/* Calls fn(ctx, f, arg) for every facet binned within [x - reach, x + reach], in the bins' order
 * (bin by bin, each bin's facets by index): the order every query sees them in. */
#define FOR_FACETS_IN_BINS(ctx, x, reach, f, body)                                                        \
    do {                                                                                                 \
        int32_t b0_[3], b1_[3];                                                                          \
        for (int d_ = 0; d_ < 3; ++d_) {                                                                 \
            b0_[d_] = bin_of(ctx, d_, (x)[d_] - (reach));                                                \
            b1_[d_] = bin_of(ctx, d_, (x)[d_] + (reach));                                                \
        }                                                                                                \
        for (int32_t k_ = b0_[2]; k_ <= b1_[2]; ++k_)                                                    \
            for (int32_t j_ = b0_[1]; j_ <= b1_[1]; ++j_)                                                \
                for (int32_t i_ = b0_[0]; i_ <= b1_[0]; ++i_) {                                          \
                    const size_t b_ = bin_index(ctx, i_, j_, k_);                                        \
                    for (int32_t q_ = ctx->facet_offsets[b_]; q_ < ctx->facet_offsets[b_ + 1]; ++q_) {   \
                        const int32_t f = ctx->facet_items[q_];                                          \
                        body                                                                             \
                    }                                                                                    \
                }                                                                                        \
    } while (0)

/* The facet lists of cand's cells (see cdc_candidates): for cell h every facet that a query about a
 * point of h's sphere (|x - x_h| <= rho_h) with a radius up to cand->radius can take, in the bins'
 * order. A facet taken has its owner within R of x and its plane nearer than R, so within R + rho_h
 * of h's centre (triangle inequality; a relative 1e-9 more for round-off). Lists beyond the cap are
 * not made (facet_offsets stays NULL for this version: the bins serve). */
static cdc_status build_facet_lists(cdc_context *ctx, cdc_candidates *cand)
{
    const int32_t nc = ctx->mesh->n_cells;
    free(cand->facet_offsets);
    free(cand->facets);
    cand->facet_offsets = cand->facets = NULL;
    cand->facets_version = 0;
    cdc_ivec list = {0};
    int32_t *offsets = malloc(((size_t)nc + 1) * sizeof *offsets);
    if (!offsets) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for wall facet lists");
    offsets[0] = 0;
    for (int32_t h = 0; h < nc && list.n <= CDC_CANDIDATE_CAP; ++h) {
        const double *xh = ctx->mesh->cell_centres + 3 * (size_t)h;
        const double reach = (cand->radius + sqrt(ctx->cell_rho2[h])) * (1.0 + 1e-9), reach2 = reach * reach;
        FOR_FACETS_IN_BINS(ctx, xh, reach, f, {
            const cdc_facet *fc = ctx->facets + f;
            if (cdc_dist2(fc->owner, xh) > reach2 || -cdc_plane_offset(&fc->plane, xh) >= reach) continue;
            if (cdc_ivec_push(&list, f) || cdc_ivec_push(&list, ctx->facet_plane[f])) {
                free(offsets);
                cdc_ivec_free(&list);
                return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for wall facet lists");
            }
        });
        offsets[h + 1] = (int32_t)(list.n / 2);
    }
    cand->facets_version = ctx->facets_version;
    if (list.n > CDC_CANDIDATE_CAP) {
        free(offsets);
        cdc_ivec_free(&list);
        return CDC_OK;
    }
    cand->facet_offsets = offsets;
    cand->facets = list.v;
    return CDC_OK;
}

cdc_status cdc_wall_planes_near(cdc_context *ctx, cdc_candidates *cand, int32_t start, const double x[3],
                                double radius, cdc_plane *planes, int *n_planes)
{
    *n_planes = 0;
    if (ctx->n_facets == 0) return CDC_OK;
    facet_query fq; /* not zeroed as a whole: known_numbers is read only up to n_known */
    fq.x = x;
    fq.radius = radius;
    fq.r2 = radius * radius * CDC_RADIUS_SLACK;
    fq.skip_by_number = radius >= 2e-3 * ctx->facet_bin;
    fq.n_known = 0;
    cdc_status st = CDC_OK;
    const int listed = cand && cand->offsets && radius <= cand->radius && start >= 0 &&
                       cdc_dist2(x, ctx->mesh->cell_centres + 3 * (size_t)start) <=
                           ctx->cell_rho2[start] * CDC_RADIUS_SLACK;
    if (listed && cand->facets_version != ctx->facets_version) st = build_facet_lists(ctx, cand);
    if (st != CDC_OK) return st;
    if (listed && cand->facet_offsets) {
        /* (facet, plane number) pairs: a face of a plane taken costs a compare, not a look-up */
        const int32_t *e = cand->facets + 2 * (size_t)cand->facet_offsets[start],
                      *end = cand->facets + 2 * (size_t)cand->facet_offsets[start + 1];
        for (; e < end && st == CDC_OK; e += 2) st = consider(ctx, &fq, e[0], e[1], planes, n_planes);
        return st;
    }
    FOR_FACETS_IN_BINS(ctx, x, radius, f, {
        st = consider(ctx, &fq, f, ctx->facet_plane[f], planes, n_planes);
        if (st != CDC_OK) return st;
    });
    return CDC_OK;
}
