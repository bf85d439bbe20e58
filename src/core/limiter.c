/*
 * limiter.c -- conservative packing limiter. Kernels with a small support (centre, divided) can put
 * more solid in a cell than fits (alpha_p > alpha_max, even > 1). Clipping would delete solid
 * volume; here the excess moves to face neighbours in sweeps: first into their free room (in
 * proportion to it), and what does not fit one hop further towards the nearest cell with room.
 * All transfers of a sweep are computed from the same state, so the result does not depend on cell
 * order. Every transfer leaves one cell and enters another: total volume is unchanged to
 * round-off. The volume that was above the limit and the number of such cells are reported.
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
        cdc_dvec_reserve(&ctx->scratch[2], nc) || cdc_dvec_reserve(&ctx->scratch[3], nc) ||
        cdc_dvec_reserve(&ctx->scratch[4], nc))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    double *vol = ctx->scratch[0].v, *room = ctx->scratch[1].v, *delta = ctx->scratch[2].v, *dist = ctx->scratch[3].v,
           *fill = ctx->scratch[4].v;

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
    /* What the limiter moves is the volume above the limit: report that (not the sum of the
     * hops it takes to reach free room). */
    double moved = 0.0;
    for (size_t c = 0; c < nc; ++c) moved += fmax(0.0, vol[c] - alpha_max * m->cell_volumes[c]);
    int sweep = 0, remaining = over;
    for (; remaining > 0 && sweep < max_sweeps; ++sweep) {
        memset(delta, 0, nc * sizeof *delta);
        /* free room; a round-off sliver is no room (else a cell just filled to the limit would
         * attract excess back and two cells could trade it for ever) */
        for (size_t c = 0; c < nc; ++c) {
            const double cap = alpha_max * m->cell_volumes[c], r = cap - vol[c];
            room[c] = r > 1e-12 * cap ? r : 0.0;
            fill[c] = 0.0;
        }
        /* hop distance of every cell to the nearest cell with room (multi-source BFS): excess that
         * finds no room next door moves downhill, so a packed block empties in about as many
         * sweeps as it is cells wide, not as many as its width squared */
        ctx->queue.n = 0;
        for (size_t c = 0; c < nc; ++c) {
            dist[c] = room[c] > 0.0 ? 0.0 : INFINITY;
            if (room[c] > 0.0 && cdc_ivec_push(&ctx->queue, (int32_t)c))
                return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
        }
        for (size_t head = 0; head < ctx->queue.n; ++head) {
            const int32_t c = ctx->queue.v[head];
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                if (dist[n] <= dist[c] + 1.0) continue;
                dist[n] = dist[c] + 1.0;
                if (cdc_ivec_push(&ctx->queue, n)) return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
            }
        }
        for (size_t c = 0; c < nc; ++c) {
            double excess = vol[c] - alpha_max * m->cell_volumes[c];
            if (excess <= 0.0) continue;
            double nb_room = 0.0;
            int n_down = 0;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                nb_room += room[n];
                n_down += dist[n] < dist[c];
            }
            /* first fill the neighbours' room, in proportion to it (requests; scaled below so that
             * several donors together never overfill a receiver) */
            const double give = fmin(excess, nb_room);
            if (give > 0.0)
                for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                    const int32_t n = ctx->cell_cells[q];
                    fill[n] += give * room[n] / nb_room;
                }
            excess -= give;
            /* the rest moves one hop towards the nearest room */
            if (excess > 0.0 && n_down > 0)
                for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                    const int32_t n = ctx->cell_cells[q];
                    if (!(dist[n] < dist[c])) continue;
                    delta[n] += excess / n_down;
                    delta[c] -= excess / n_down;
                }
        }
        /* accepted share of every receiver: all its room at most */
        for (size_t c = 0; c < nc; ++c) fill[c] = fill[c] > room[c] ? room[c] / fill[c] : 1.0;
        for (size_t c = 0; c < nc; ++c) {
            const double excess = vol[c] - alpha_max * m->cell_volumes[c];
            if (excess <= 0.0) continue;
            double nb_room = 0.0;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q)
                nb_room += room[ctx->cell_cells[q]];
            const double give = fmin(excess, nb_room);
            if (give <= 0.0) continue;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                const double share = give * room[n] / nb_room * fill[n];
                delta[n] += share;
                delta[c] -= share;
            }
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
