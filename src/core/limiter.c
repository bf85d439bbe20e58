/*
 * limiter.c -- conservative packing limiter. Kernels with a small support (centre, divided) can put
 * more solid in a cell than fits (alpha_p > alpha_max, even > 1). Clipping would delete solid
 * volume; here the excess moves to face neighbours in sweeps: first into their free room (in
 * proportion to it), and what does not fit one hop further towards the nearest cell with room.
 * All transfers of a sweep are computed from the same state, so the result does not depend on cell
 * order. Every transfer leaves one cell and enters another: total volume is unchanged to
 * round-off. The volume that was above the limit and the number of such cells are reported.
 *
 * Parallel (a halo set with cdc_context_set_halo): processor faces are faces like the internal
 * ones. A transfer across one is computed on both sides from the same exchanged numbers in the same
 * order, so what leaves one rank is bit for bit what enters the other; the hop distances are those
 * of the whole mesh; the sweeps stop on all ranks together. The result is the serial one up to the
 * order of summation (round-off).
 */
#include "internal.h"

#include <math.h>
#include <string.h>

_Static_assert(CDC_N_SCRATCH >= 8, "the packing limiter uses scratch vectors 0..7");

/* "no cell with room is reachable": finite, so it crosses any exchange unchanged */
#define FAR 1e300

/* nbr[i] = the other rank's value across processor face i (no-op without a halo) */
static cdc_status exchange(cdc_context *ctx, const double *cell_values, double *nbr)
{
    if (ctx->has_halo && ctx->halo.exchange(ctx->halo.user, cell_values, nbr))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "packing limiter: the halo exchange failed");
    return CDC_OK;
}

/* values summed over all ranks (no-op without a halo) */
static cdc_status global_sum(cdc_context *ctx, double *values, int n)
{
    if (ctx->has_halo && ctx->halo.sum(ctx->halo.user, values, n))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "packing limiter: the global sum failed");
    return CDC_OK;
}

/* Shortest path in face hops from every cell to a cell with room (dist 0 there), across ranks:
 * label-correcting search from the queued cells, then cells next to processor faces take the other
 * side's distance + 1 and the search goes on, until no rank changes. */
static cdc_status hop_distances(cdc_context *ctx, const double *room, double *dist, double *nbr_dist)
{
    const size_t nc = (size_t)ctx->mesh->n_cells;
    ctx->queue.n = 0;
    for (size_t c = 0; c < nc; ++c) {
        dist[c] = room[c] > 0.0 ? 0.0 : FAR;
        if (room[c] > 0.0 && cdc_ivec_push(&ctx->queue, (int32_t)c))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    }
    for (;;) {
        for (size_t head = 0; head < ctx->queue.n; ++head) {
            const int32_t c = ctx->queue.v[head];
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                if (dist[n] <= dist[c] + 1.0) continue;
                dist[n] = dist[c] + 1.0;
                if (cdc_ivec_push(&ctx->queue, n)) return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
            }
        }
        if (!ctx->has_halo) return CDC_OK;
        cdc_status st = exchange(ctx, dist, nbr_dist);
        if (st != CDC_OK) return st;
        ctx->queue.n = 0;
        for (int32_t i = 0; i < ctx->halo.n_faces; ++i) {
            const int32_t c = ctx->halo.cell[i];
            if (dist[c] <= nbr_dist[i] + 1.0) continue;
            dist[c] = nbr_dist[i] + 1.0;
            if (cdc_ivec_push(&ctx->queue, c)) return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
        }
        double changed = (double)ctx->queue.n;
        if ((st = global_sum(ctx, &changed, 1)) != CDC_OK) return st;
        if (changed == 0.0) return CDC_OK; /* nbr_dist is that of the final distances */
    }
}

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
    const int32_t nf = ctx->has_halo ? ctx->halo.n_faces : 0;
    const int32_t *fcell = ctx->has_halo ? ctx->halo.cell : NULL;
    for (int k = 0; k < 8; ++k)
        if (cdc_dvec_reserve(&ctx->scratch[k], nc + 1)) return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    if (cdc_dvec_reserve(&ctx->halo_work, 6 * (size_t)nf + 1))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    /* per cell */
    double *vol = ctx->scratch[0].v, *room = ctx->scratch[1].v, *delta = ctx->scratch[2].v, *dist = ctx->scratch[3].v,
           *fill = ctx->scratch[4].v, *give = ctx->scratch[5].v, *nb_room = ctx->scratch[6].v, *hop = ctx->scratch[7].v;
    /* per processor face: the other side's cell values */
    double *f_room = ctx->halo_work.v, *f_dist = f_room + nf, *f_give = f_dist + nf, *f_nb_room = f_give + nf,
           *f_hop = f_nb_room + nf, *f_fill = f_hop + nf;
    cdc_status st;

    /* Work in solid volumes (m^3): transfers are then exact opposites. */
    double totals[2] = {0.0, 0.0}; /* solid, room at the limit */
    int32_t over = 0;
    for (size_t c = 0; c < nc; ++c) {
        vol[c] = alpha_p[c] * m->cell_volumes[c];
        totals[0] += vol[c];
        totals[1] += alpha_max * m->cell_volumes[c];
        if (alpha_p[c] > alpha_max) ++over;
    }
    if ((st = global_sum(ctx, totals, 2)) != CDC_OK) return st;
    if (totals[0] > totals[1])
        return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                        "packing limiter: the solid volume %g m^3 exceeds alphaMax times the mesh volume (%g m^3)",
                        totals[0], totals[1]);
    /* What the limiter moves is the volume above the limit: report that (not the sum of the
     * hops it takes to reach free room). This rank's share; the caller sums the ranks. */
    double moved = 0.0;
    for (size_t c = 0; c < nc; ++c) moved += fmax(0.0, vol[c] - alpha_max * m->cell_volumes[c]);
    double remaining = (double)over;
    if ((st = global_sum(ctx, &remaining, 1)) != CDC_OK) return st;
    int sweep = 0;
    for (; remaining > 0.0 && sweep < max_sweeps; ++sweep) {
        memset(delta, 0, nc * sizeof *delta);
        /* free room; a round-off sliver is no room (else a cell just filled to the limit would
         * attract excess back and two cells could trade it for ever) */
        for (size_t c = 0; c < nc; ++c) {
            const double cap = alpha_max * m->cell_volumes[c], r = cap - vol[c];
            room[c] = r > 1e-12 * cap ? r : 0.0;
            fill[c] = 0.0;
        }
        if ((st = exchange(ctx, room, f_room)) != CDC_OK) return st;
        /* hop distance of every cell to the nearest cell with room: excess that finds no room next
         * door moves downhill, so a packed block empties in about as many sweeps as it is cells
         * wide, not as many as its width squared */
        if ((st = hop_distances(ctx, room, dist, f_dist)) != CDC_OK) return st;
        /* donors: what they give into the neighbours' room, and what hops on. First each donor's
         * neighbours: their room, and how many are downhill (kept in hop[] until the hop share is
         * known) */
        for (size_t c = 0; c < nc; ++c) {
            give[c] = nb_room[c] = hop[c] = 0.0;
            if (vol[c] - alpha_max * m->cell_volumes[c] <= 0.0) continue;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                nb_room[c] += room[ctx->cell_cells[q]];
                hop[c] += dist[ctx->cell_cells[q]] < dist[c];
            }
        }
        for (int32_t i = 0; i < nf; ++i) {
            nb_room[fcell[i]] += f_room[i];
            hop[fcell[i]] += f_dist[i] < dist[fcell[i]];
        }
        for (size_t c = 0; c < nc; ++c) {
            const double excess = vol[c] - alpha_max * m->cell_volumes[c];
            if (excess <= 0.0) { hop[c] = 0.0; continue; }
            /* first fill the neighbours' room, in proportion to it (requests; scaled below so that
             * several donors together never overfill a receiver) */
            give[c] = fmin(excess, nb_room[c]);
            /* the rest moves one hop towards the nearest room, shared by the downhill neighbours */
            const double rest = excess - give[c];
            hop[c] = rest > 0.0 && hop[c] > 0.0 ? rest / hop[c] : 0.0;
        }
        if ((st = exchange(ctx, give, f_give)) != CDC_OK || (st = exchange(ctx, nb_room, f_nb_room)) != CDC_OK ||
            (st = exchange(ctx, hop, f_hop)) != CDC_OK)
            return st;
        /* requests and hops, internal faces */
        for (size_t c = 0; c < nc; ++c) {
            if (give[c] <= 0.0 && hop[c] <= 0.0) continue;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                if (give[c] > 0.0) fill[n] += give[c] * room[n] / nb_room[c];
                if (hop[c] > 0.0 && dist[n] < dist[c]) {
                    delta[n] += hop[c];
                    delta[c] -= hop[c];
                }
            }
        }
        /* processor faces: this rank's donors send, the other rank's donors give here; each side
         * evaluates the same expression of the same numbers */
        for (int32_t i = 0; i < nf; ++i) {
            const int32_t c = fcell[i];
            if (hop[c] > 0.0 && f_dist[i] < dist[c]) delta[c] -= hop[c];
            if (f_hop[i] > 0.0 && dist[c] < f_dist[i]) delta[c] += f_hop[i];
            if (f_give[i] > 0.0) fill[c] += f_give[i] * room[c] / f_nb_room[i];
        }
        /* accepted share of every receiver: all its room at most */
        for (size_t c = 0; c < nc; ++c) fill[c] = fill[c] > room[c] ? room[c] / fill[c] : 1.0;
        if ((st = exchange(ctx, fill, f_fill)) != CDC_OK) return st;
        for (size_t c = 0; c < nc; ++c) {
            if (give[c] <= 0.0) continue;
            for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
                const int32_t n = ctx->cell_cells[q];
                const double share = give[c] * room[n] / nb_room[c] * fill[n];
                delta[n] += share;
                delta[c] -= share;
            }
        }
        for (int32_t i = 0; i < nf; ++i) {
            const int32_t c = fcell[i];
            if (give[c] > 0.0) delta[c] -= give[c] * f_room[i] / nb_room[c] * f_fill[i];
            if (f_give[i] > 0.0) delta[c] += f_give[i] * room[c] / f_nb_room[i] * fill[c];
        }
        remaining = 0.0;
        for (size_t c = 0; c < nc; ++c) {
            vol[c] += delta[c];
            if (vol[c] > alpha_max * m->cell_volumes[c] * (1.0 + 1e-12)) remaining += 1.0;
        }
        if ((st = global_sum(ctx, &remaining, 1)) != CDC_OK) return st;
    }
    if (remaining > 0.0)
        return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                        "packing limiter: %.0f cells still above alphaMax %g after %d sweeps", remaining,
                        alpha_max, sweep);
    for (size_t c = 0; c < nc; ++c) alpha_p[c] = vol[c] / m->cell_volumes[c];
    if (moved_volume) *moved_volume = moved;
    if (n_limited_cells) *n_limited_cells = over;
    return CDC_OK;
}
