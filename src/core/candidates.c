/*
 * candidates.c -- per-cell candidate lists for the centre-within searches of the expansion kernels
 * (bigParticle with n, twoGrid, gaussian).
 *
 * For each cell h, the list holds the cells whose centre lies within R + rho_h of h's centre, where
 * rho_h is the distance from h's centre to the farthest corner of its bounding box (every point of
 * h is within rho_h of its centre). A cell within r <= R of a point x of h is then within R + rho_h
 * of h's centre (triangle inequality), so a search about x becomes a filter over h's list instead
 * of a flood fill over the face graph: the mesh does not move, the lists are made once per kernel
 * set and largest radius. The lists come from a flood fill from h (neighbourhood.c), so a kernel
 * still does not jump across a thin wall to cells that are near in space but far through the mesh.
 * On a mesh of boxes the filter takes exactly the cells the flood fill about x takes; on distorted
 * cells it may also take a rim cell within r of x that the flood about x reaches only through cells
 * farther than r (a superset, never fewer cells).
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>

/* Squared radius of cell c about its centre: its centre to the farthest corner of its box. */
static double cell_rho2(const cdc_context *ctx, int32_t c)
{
    const double *bb = ctx->cell_bbox + 6 * (size_t)c, *xc = ctx->mesh->cell_centres + 3 * (size_t)c;
    double r2 = 0.0;
    for (int d = 0; d < 3; ++d) {
        const double a = xc[d] - bb[d], b = bb[3 + d] - xc[d];
        r2 += (a > b ? a * a : b * b);
    }
    return r2;
}

void cdc_candidates_free(cdc_candidates *cand)
{
    free(cand->offsets);
    free(cand->cells);
    cand->offsets = NULL;
    cand->cells = NULL;
    cand->radius = 0.0;
}

/* The lists for radius R; CDC_ERR_NOMEM only when memory runs out, too_large set (and no lists)
 * when they would exceed CDC_CANDIDATE_CAP entries. */
static cdc_status build(cdc_context *ctx, cdc_candidates *cand, double R)
{
    const int32_t nc = ctx->mesh->n_cells;
    cdc_candidates_free(cand);
    cdc_ivec cells = {0};
    int32_t *offsets = malloc(((size_t)nc + 1) * sizeof *offsets);
    if (!offsets) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for kernel candidate lists");
    offsets[0] = 0;
    for (int32_t h = 0; h < nc; ++h) {
        const double *xh = ctx->mesh->cell_centres + 3 * (size_t)h;
        cdc_status st = cdc_flood_within(ctx, xh, h, 0, R + sqrt(cell_rho2(ctx, h)), &ctx->near_cells);
        if (st != CDC_OK) {
            free(offsets);
            cdc_ivec_free(&cells);
            return st;
        }
        if (cells.n + ctx->near_cells.n > CDC_CANDIDATE_CAP) {
            free(offsets);
            cdc_ivec_free(&cells);
            cand->too_large = R;
            return CDC_OK;
        }
        if (cdc_ivec_reserve(&cells, cells.n + ctx->near_cells.n + 1)) {
            free(offsets);
            cdc_ivec_free(&cells);
            return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory for kernel candidate lists");
        }
        for (size_t q = 0; q < ctx->near_cells.n; ++q) cells.v[cells.n++] = ctx->near_cells.v[q];
        offsets[h + 1] = (int32_t)cells.n;
    }
    cand->offsets = offsets;
    cand->cells = cells.v;
    cand->radius = R;
    return CDC_OK;
}

cdc_status cdc_cells_within(cdc_context *ctx, cdc_candidates *cand, const double x[3], int32_t start,
                            int seed_only, double radius, cdc_ivec *cells)
{
    if (cand && radius > cand->radius && cand->wanted >= radius &&
        !(cand->too_large > 0.0 && cand->wanted >= cand->too_large)) {
        cdc_status st = build(ctx, cand, cand->wanted);
        if (st != CDC_OK) return st;
    }
    const double *xs = ctx->mesh->cell_centres + 3 * (size_t)start;
    if (!cand || radius > cand->radius || cdc_dist2(x, xs) > cell_rho2(ctx, start) * CDC_RADIUS_SLACK)
        return cdc_flood_within(ctx, x, start, seed_only, radius, cells);
    /* the filter: every cell of the list whose centre is within the radius */
    const double *xv = ctx->cell_xv, r2 = radius * radius * CDC_RADIUS_SLACK;
    if (cdc_ivec_reserve(cells, (size_t)(cand->offsets[start + 1] - cand->offsets[start]) + 1))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory in cell search");
    int32_t *taken = cells->v;
    size_t n = 0;
    for (int32_t q = cand->offsets[start]; q < cand->offsets[start + 1]; ++q) {
        const int32_t c = cand->cells[q];
        taken[n] = c; /* written always, kept when within: no branch to mispredict on the kernel's rim */
        n += cdc_dist2(xv + 4 * (size_t)c, x) <= r2;
    }
    cells->n = n;
    /* the host of a local particle is always in (as in the flood fill), a ghost's start cell only
     * when within the radius */
    if (!seed_only && !(cdc_dist2(xs, x) <= r2)) {
        if (cdc_ivec_push(cells, start)) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory in cell search");
    }
    return CDC_OK;
}
