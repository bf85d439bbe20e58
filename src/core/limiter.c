/*
 * limiter.c -- conservative packing limiter. Kernels with a small support (centre, divided) can put
 * more solid in a cell than fits (alpha_p > alpha_max, even > 1). Clipping would delete solid
 * volume; here the excess moves to face neighbours in proportion to their free room, in sweeps
 * (all transfers of a sweep computed from the same state, so the result does not depend on cell
 * order). Every transfer leaves one cell and enters another: total volume is unchanged to
 * round-off. The moved volume and the number of cells that were over the limit are reported.
 */
#include "internal.h"

#include <math.h>
#include <string.h>

cdc_status cdc_limit_packing(cdc_context *ctx, double alpha_max, int max_sweeps, double *alpha_p,
                             double *moved_volume, int32_t *n_limited_cells)
{
    if (!ctx || !alpha_p) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "packing limiter: NULL argument");
    if (!(alpha_max > 0.0 && alpha_max < 1.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "packing limiter: alphaMax %g is invalid (must be in (0, 1))",
                        alpha_max);
    if (max_sweeps <= 0) max_sweeps = 100;
    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells;
    if (cdc_dvec_reserve(&ctx->scratch[0], nc) || cdc_dvec_reserve(&ctx->scratch[1], nc) ||
        cdc_dvec_reserve(&ctx->scratch[2], nc))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    double *vol = ctx->scratch[0].v, *room = ctx->scratch[1].v, *delta = ctx->scratch[2].v;

    /* Work in solid volumes (m^3): transfers are then exact opposites. */
    double total_room = 0.0, total_solid = 0.0;
    int32_t over = 0;
    for (size_t c = 0; c < nc; ++c) {
        vol[c] = alpha_p[c] * m->cell_volumes[c];
        total_solid += vol[c];
        total_room += alpha_max * m->cell_volumes[c];
        if (alpha_p[c] > alpha_max) ++over;
    }
    if (total_solid > total_room)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                        "packing limiter: the solid volume %g m^3 exceeds alphaMax times the mesh volume (%g m^3)",
                        total_solid, total_room);
    double moved = 0.0;
    int sweep = 0, remaining = over;
    for (; remaining > 0 && sweep < max_sweeps; ++sweep) {
        memset(delta, 0, nc * sizeof *delta);
        for (size_t c = 0; c < nc; ++c) room[c] = fmax(0.0, alpha_max * m->cell_volumes[c] - vol[c]);
        for (size_t c = 0; c < nc; ++c) {
            const double excess = vol[c] - alpha_max * m->cell_volumes[c];
            if (excess <= 0.0) continue;
            double nb_room = 0.0;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q)
                nb_room += room[ctx->cell_cells[q]];
            /* With no room next door, push everything over to the neighbours anyway (share by
             * count): they pass it on in the next sweep. */
            const int32_t nn = ctx->cell_cell_offsets[c + 1] - ctx->cell_cell_offsets[c];
            if (nn == 0) continue;
            const double give = nb_room > 0.0 ? fmin(excess, nb_room) : excess;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                const double share = nb_room > 0.0 ? give * room[n] / nb_room : give / nn;
                delta[n] += share;
                delta[c] -= share;
            }
            moved += give;
        }
        remaining = 0;
        for (size_t c = 0; c < nc; ++c) {
            vol[c] += delta[c];
            if (vol[c] > alpha_max * m->cell_volumes[c] * (1.0 + 1e-12)) ++remaining;
        }
    }
    if (remaining > 0)
        return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                        "packing limiter: %d cells still above alphaMax %g after %d sweeps", remaining,
                        alpha_max, sweep);
    for (size_t c = 0; c < nc; ++c) alpha_p[c] = vol[c] / m->cell_volumes[c];
    if (moved_volume) *moved_volume = moved;
    if (n_limited_cells) *n_limited_cells = over;
    return CDC_OK;
}
