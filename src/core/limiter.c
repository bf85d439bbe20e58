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

/* The limiter's work arrays: per cell, and per processor face the other side's values. */
typedef struct {
    double *vol, *room, *delta, *dist, *fill, *give, *nb_room, *hop;
    double *f_room, *f_dist, *f_give, *f_nb_room, *f_hop, *f_fill;
    int32_t nf;
    const int32_t *fcell;
} limiter_work;

/* A sweep's plan: every cell's free room and hop distance to room; every donor's request into its
 * neighbours' room (give) and the share of the rest that hops one cell towards room (hop). */
static cdc_status plan_sweep(cdc_context *ctx, double alpha_max, limiter_work *w)
{
    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells;
    cdc_status st;
    /* free room; a round-off sliver is no room (else a cell just filled to the limit would
     * attract excess back and two cells could trade it for ever) */
    for (size_t c = 0; c < nc; ++c) {
        const double cap = alpha_max * m->cell_volumes[c], r = cap - w->vol[c];
        w->room[c] = r > 1e-12 * cap ? r : 0.0;
        w->fill[c] = 0.0;
    }
    if ((st = exchange(ctx, w->room, w->f_room)) != CDC_OK) return st;
    /* hop distance of every cell to the nearest cell with room: excess that finds no room next
     * door moves downhill, so a packed block empties in about as many sweeps as it is cells
     * wide, not as many as its width squared */
    if ((st = hop_distances(ctx, w->room, w->dist, w->f_dist)) != CDC_OK) return st;
    /* donors: what they give into the neighbours' room, and what hops on. First each donor's
     * neighbours: their room, and how many are downhill (kept in hop[] until the hop share is
     * known) */
    for (size_t c = 0; c < nc; ++c) {
        w->give[c] = w->nb_room[c] = w->hop[c] = 0.0;
        if (w->vol[c] - alpha_max * m->cell_volumes[c] <= 0.0) continue;
        for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
            w->nb_room[c] += w->room[ctx->cell_cells[q]];
            w->hop[c] += w->dist[ctx->cell_cells[q]] < w->dist[c];
        }
    }
    for (int32_t i = 0; i < w->nf; ++i) {
        w->nb_room[w->fcell[i]] += w->f_room[i];
        w->hop[w->fcell[i]] += w->f_dist[i] < w->dist[w->fcell[i]];
    }
    for (size_t c = 0; c < nc; ++c) {
        const double excess = w->vol[c] - alpha_max * m->cell_volumes[c];
        if (excess <= 0.0) { w->hop[c] = 0.0; continue; }
        /* first fill the neighbours' room, in proportion to it (requests; scaled below so that
         * several donors together never overfill a receiver) */
        w->give[c] = fmin(excess, w->nb_room[c]);
        /* the rest moves one hop towards the nearest room, shared by the downhill neighbours */
        const double rest = excess - w->give[c];
        w->hop[c] = rest > 0.0 && w->hop[c] > 0.0 ? rest / w->hop[c] : 0.0;
    }
    if ((st = exchange(ctx, w->give, w->f_give)) != CDC_OK || (st = exchange(ctx, w->nb_room, w->f_nb_room)) != CDC_OK ||
        (st = exchange(ctx, w->hop, w->f_hop)) != CDC_OK)
        return st;
    return CDC_OK;
}

/* A sweep's moves from its plan, into delta: the hops, and the requests scaled so that no receiver
 * takes more than its room. Every transfer is one expression added to one cell and subtracted from
 * the other (across a processor face, each side evaluates the same expression of the same numbers). */
static cdc_status move_sweep(cdc_context *ctx, limiter_work *w)
{
    const size_t nc = (size_t)ctx->mesh->n_cells;
    const double *room = w->room, *dist = w->dist, *give = w->give, *nb_room = w->nb_room, *hop = w->hop;
    double *fill = w->fill, *delta = w->delta;
    memset(delta, 0, nc * sizeof *delta);
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
    /* processor faces: this rank's donors send, the other rank's donors give here */
    for (int32_t i = 0; i < w->nf; ++i) {
        const int32_t c = w->fcell[i];
        if (hop[c] > 0.0 && w->f_dist[i] < dist[c]) delta[c] -= hop[c];
        if (w->f_hop[i] > 0.0 && dist[c] < w->f_dist[i]) delta[c] += w->f_hop[i];
        if (w->f_give[i] > 0.0) fill[c] += w->f_give[i] * room[c] / w->f_nb_room[i];
    }
    /* accepted share of every receiver: all its room at most */
    for (size_t c = 0; c < nc; ++c) fill[c] = fill[c] > room[c] ? room[c] / fill[c] : 1.0;
    cdc_status st = exchange(ctx, fill, w->f_fill);
    if (st != CDC_OK) return st;
    for (size_t c = 0; c < nc; ++c) {
        if (give[c] <= 0.0) continue;
        for (int32_t q = ctx->cell_cell_offsets[c]; q < ctx->cell_cell_offsets[c + 1]; ++q) {
            const int32_t n = ctx->cell_cells[q];
            const double share = give[c] * room[n] / nb_room[c] * fill[n];
            delta[n] += share;
            delta[c] -= share;
        }
    }
    for (int32_t i = 0; i < w->nf; ++i) {
        const int32_t c = w->fcell[i];
        if (give[c] > 0.0) delta[c] -= give[c] * w->f_room[i] / nb_room[c] * w->f_fill[i];
        if (w->f_give[i] > 0.0) delta[c] += w->f_give[i] * room[c] / w->f_nb_room[i] * fill[c];
    }
    return CDC_OK;
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
    for (int k = 0; k < 8; ++k)
        if (cdc_dvec_reserve(&ctx->scratch[k], nc + 1)) return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    if (cdc_dvec_reserve(&ctx->halo_work, 6 * (size_t)nf + 1))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "packing limiter: out of memory");
    double *f = ctx->halo_work.v;
    limiter_work w = {ctx->scratch[0].v, ctx->scratch[1].v, ctx->scratch[2].v, ctx->scratch[3].v,
                      ctx->scratch[4].v, ctx->scratch[5].v, ctx->scratch[6].v, ctx->scratch[7].v,
                      f, f + nf, f + 2 * nf, f + 3 * nf, f + 4 * nf, f + 5 * nf,
                      nf, ctx->has_halo ? ctx->halo.cell : NULL};
    double *vol = w.vol;
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
        if ((st = plan_sweep(ctx, alpha_max, &w)) != CDC_OK || (st = move_sweep(ctx, &w)) != CDC_OK) return st;
        remaining = 0.0;
        for (size_t c = 0; c < nc; ++c) {
            vol[c] += w.delta[c];
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
