/*
 * neighbourhood.c -- the cells around a particle, by flood fill across faces from its host cell
 * (the cell-topology search of Zhang et al. 2023 §II.B, the "linked-list search" of §II.E),
 * and the choice and images of the wall planes the wall-aware kernels mirror across (the planes
 * near a particle are found in wall_facets.c).
 */
#include "internal.h"

#include <math.h>

/* Which cells a search takes: those whose centre is within the radius, or whose bounding box
 * overlaps the sphere. A switch, not a function pointer, so the test is inlined in the flood
 * (the indirect call was 16 % of a gaussian kernel build: perf, bench -m gaussian_b3d). */
enum accept_kind { CENTRE_WITHIN, BOX_OVERLAPS };

static inline int accepts(const cdc_context *ctx, enum accept_kind kind, int32_t c, const double x[3],
                          double radius)
{
    if (kind == CENTRE_WITHIN)
        return cdc_dist2(ctx->mesh->cell_centres + 3 * (size_t)c, x) <= radius * radius * CDC_RADIUS_SLACK;
    return cdc_box_dist2(ctx->cell_bbox + 6 * (size_t)c, x) < radius * radius;
}

/* Breadth-first over the face neighbours: the cells accepted form the neighbourhood; the search
 * expands from them and from the start cell (which may itself lie outside, seed_only). A cell is
 * tested when first seen and queued only if accepted, so the rejected rim costs one test each. */
static cdc_status flood(cdc_context *ctx, const double x[3], int32_t host, int seed_only, double radius,
                        enum accept_kind kind, cdc_ivec *cells)
{
    const int32_t s = cdc_next_stamp(ctx);
    cells->n = 0;
    ctx->queue.n = 0;
    if (cdc_ivec_push(&ctx->queue, host)) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory in cell search");
    ctx->stamp[host] = s;
    const int host_member = accepts(ctx, kind, host, x, radius) || !seed_only;
    for (size_t head = 0; head < ctx->queue.n; ++head) {
        const int32_t c = ctx->queue.v[head];
        const int member = c != host || host_member; /* every other queued cell was accepted */
        if (member && cdc_ivec_push(cells, c)) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory in cell search");
        for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
            const int32_t nb = ctx->cell_cells[q];
            if (ctx->stamp[nb] == s) continue;
            ctx->stamp[nb] = s;
            if (accepts(ctx, kind, nb, x, radius) && cdc_ivec_push(&ctx->queue, nb))
                return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory in cell search");
        }
    }
    return CDC_OK;
}

cdc_status cdc_flood_within(cdc_context *ctx, const double x[3], int32_t start, int seed_only, double radius,
                            cdc_ivec *cells)
{
    return flood(ctx, x, start, seed_only, radius, CENTRE_WITHIN, cells);
}

cdc_status cdc_cells_overlapping(cdc_context *ctx, const double x[3], int32_t start, int seed_only,
                                 double radius, cdc_ivec *cells)
{
    return flood(ctx, x, start, seed_only, radius, BOX_OVERLAPS, cells);
}

/* Order of the facets for cdc_nearest_wall_planes: nearer first; equal distances by normal. */
static int nearer(const cdc_plane *a, double da, const cdc_plane *b, double db)
{
    if (da != db) return da < db;
    for (int d = 0; d < 3; ++d)
        if (a->normal[d] != b->normal[d]) return a->normal[d] < b->normal[d];
    return 0;
}

int cdc_nearest_wall_planes(const double x[3], cdc_plane *planes, int n_planes)
{
    double dist[CDC_MAX_WALL_FACETS];
    for (int k = 0; k < n_planes; ++k) dist[k] = -cdc_plane_offset(planes + k, x);
    /* insertion sort: a few dozen facets at most */
    for (int k = 1; k < n_planes; ++k) {
        const cdc_plane p = planes[k];
        const double dp = dist[k];
        int j = k;
        for (; j > 0 && nearer(&p, dp, planes + j - 1, dist[j - 1]); --j) {
            planes[j] = planes[j - 1];
            dist[j] = dist[j - 1];
        }
        planes[j] = p;
        dist[j] = dp;
    }
    int kept = 0;
    for (int k = 0; k < n_planes; ++k) {
        int same_wall = 0;
        for (int q = 0; q < kept && !same_wall; ++q) {
            const double *a = planes[k].normal, *b = planes[q].normal;
            same_wall = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] > CDC_SAME_WALL_COS;
        }
        if (same_wall) continue;
        if (kept == CDC_MAX_PLANES) return CDC_MAX_PLANES + 1;
        planes[kept++] = planes[k];
    }
    return kept;
}

static void reflect(const double x[3], const cdc_plane *p, double out[3])
{
    const double s = cdc_plane_offset(p, x);
    for (int d = 0; d < 3; ++d) out[d] = x[d] - 2.0 * s * p->normal[d];
}

int cdc_mirror_images(const double x[3], const cdc_plane *planes, int n_planes, double reach,
                      double images[][3])
{
    const double same2 = (1e-9 * reach) * (1e-9 * reach);
    int n = 1;
    for (int d = 0; d < 3; ++d) images[0][d] = x[d];
    for (int head = 0; head < n; ++head)
        for (int k = 0; k < n_planes; ++k) {
            double y[3];
            reflect(images[head], planes + k, y);
            double beyond = 0.0; /* how far y lies outside the domain side of the planes */
            for (int q = 0; q < n_planes; ++q) beyond = fmax(beyond, cdc_plane_offset(planes + q, y));
            if (beyond >= reach) continue;
            int known = 0;
            for (int m = 0; m < n && !known; ++m) known = cdc_dist2(y, images[m]) <= same2;
            if (known) continue;
            if (n == CDC_MAX_IMAGES) return -1;
            for (int d = 0; d < 3; ++d) images[n][d] = y[d];
            ++n;
        }
    return n;
}
