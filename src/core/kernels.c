/*
 * kernels.c -- the driver: locate particles, let the selected method append raw weights, merge
 * duplicate cells, normalise to sum 1. Using the kernels (alpha_p, spreading, gathering) is in
 * kernel_use.c.
 */
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

int cdc_kernel_add(cdc_kernel_builder *b, int32_t cell, double w)
{
    if (cdc_ivec_push(b->cells, cell)) return -1;
    if (cdc_dvec_push(b->weights, w)) return -1;
    return 0;
}

cdc_status cdc_kernels_create(cdc_context *ctx, const char *method, const cdc_kernel_params *params,
                              cdc_kernels **out)
{
    if (!ctx || !out) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_kernels_create: NULL argument");
    const cdc_method *m = cdc_find_method(method);
    if (!m)
        return cdc_fail(ctx, CDC_ERR_UNKNOWN, "unknown void fraction method '%s'; valid methods are: %s",
                        method ? method : "(null)", cdc_method_list());
    cdc_kernel_params prm;
    memset(&prm, 0, sizeof prm);
    if (params) prm = *params;
    cdc_status st = m->check(ctx, &prm);
    if (st != CDC_OK) return st;

    cdc_kernels *k = calloc(1, sizeof *k);
    if (!k) return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory creating kernels");
    k->ctx = ctx;
    k->method = m;
    k->prm = prm;
    k->slot = malloc((size_t)ctx->mesh->n_cells * sizeof(int32_t));
    k->slot_stamp = calloc((size_t)ctx->mesh->n_cells, sizeof(int32_t));
    if (!k->slot || !k->slot_stamp || cdc_ivec_push(&k->offsets, 0)) {
        cdc_kernels_destroy(k);
        return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory creating kernels");
    }
    *out = k;
    return CDC_OK;
}

void cdc_kernels_destroy(cdc_kernels *k)
{
    if (!k) return;
    cdc_ivec_free(&k->offsets);
    cdc_ivec_free(&k->cells);
    cdc_dvec_free(&k->weights);
    cdc_ivec_free(&k->hosts);
    cdc_dvec_free(&k->raw_sums);
    cdc_ivec_free(&k->fallback_pos);
    cdc_ivec_free(&k->raw_cells);
    cdc_dvec_free(&k->raw_weights);
    cdc_candidates_free(&k->cand);
    free(k->slot);
    free(k->slot_stamp);
    free(k->outside_ids);
    free(k);
}


/* Everything that can be said about one particle set before touching any output. The largest
 * reach is noted for the candidate lists. A kernel larger than the whole mesh is an error in serial
 * (whole_mesh); one rank's part of a mesh may be smaller than a kernel. */
static cdc_status check_particles(cdc_kernels *k, const cdc_particles *p, int whole_mesh)
{
    cdc_context *ctx = k->ctx;
    if (!p || p->n < 0 || (p->n > 0 && (!p->position || !p->radius)))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "particles: NULL array or negative count");
    const double *lo = ctx->mesh_lo, *hi = ctx->mesh_hi;
    const double diag = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2]));
    for (int32_t i = 0; i < p->n; ++i) {
        const double *x = p->position + 3 * (size_t)i;
        const double r = p->radius[i];
        if (!isfinite(x[0]) || !isfinite(x[1]) || !isfinite(x[2]))
            return cdc_fail(ctx, CDC_ERR_PARTICLE, "particle %lld: position (%g %g %g) is not finite",
                            (long long)cdc_particle_id(p, i), x[0], x[1], x[2]);
        if (!(r > 0.0) || !isfinite(r))
            return cdc_fail(ctx, CDC_ERR_PARTICLE, "particle %lld: radius %g is invalid (must be > 0)",
                            (long long)cdc_particle_id(p, i), r);
        const double reach = k->method->reach(&k->prm, r);
        if (reach > k->cand.wanted) k->cand.wanted = reach;
        if (whole_mesh && reach > diag)
            return cdc_fail(ctx, CDC_ERR_KERNEL,
                            "particle %lld: the %s kernel reaches %g m, more than the whole mesh (diagonal "
                            "%g m); reduce the expansion factor or bandwidth",
                            (long long)cdc_particle_id(p, i), k->method->name, reach, diag);
    }
    return CDC_OK;
}

/* Merge the raw entries of one particle (same cell twice -> one entry); returns their sum.
 * Entries a method made distinct are copied as they are. */
static cdc_status append_merged(cdc_kernels *k, int distinct, double *raw_sum)
{
    if (distinct) {
        const size_t n = k->raw_cells.n, at = k->cells.n;
        if (cdc_ivec_reserve(&k->cells, at + n + 1) || cdc_dvec_reserve(&k->weights, at + n + 1))
            return cdc_fail(k->ctx, CDC_ERR_NOMEM, "out of memory storing kernels");
        double sum = 0.0;
        for (size_t q = 0; q < n; ++q) {
            sum += k->raw_weights.v[q];
            k->cells.v[at + q] = k->raw_cells.v[q];
            k->weights.v[at + q] = k->raw_weights.v[q];
        }
        k->cells.n = k->weights.n = at + n;
        *raw_sum = sum;
        return CDC_OK;
    }
    const int32_t s = ++k->slot_now;
    const size_t start = k->cells.n;
    double sum = 0.0;
    for (size_t q = 0; q < k->raw_cells.n; ++q) {
        const int32_t c = k->raw_cells.v[q];
        const double w = k->raw_weights.v[q];
        sum += w;
        if (k->slot_stamp[c] == s) {
            k->weights.v[k->slot[c]] += w;
            continue;
        }
        k->slot_stamp[c] = s;
        k->slot[c] = (int32_t)k->cells.n;
        if (cdc_ivec_push(&k->cells, c) || cdc_dvec_push(&k->weights, w))
            return cdc_fail(k->ctx, CDC_ERR_NOMEM, "out of memory storing kernels");
    }
    (void)start;
    *raw_sum = sum;
    return CDC_OK;
}

static cdc_status no_weight(cdc_kernels *k, int64_t id)
{
    return cdc_fail(k->ctx, CDC_ERR_KERNEL, "particle %lld: %s kernel has no positive weight", (long long)id,
                    k->method->name);
}

/* Serial: merge, fall back to the method's fallback cell when nothing else got weight, normalise. */
static cdc_status append_normalised(cdc_kernels *k, int64_t id, int distinct, int32_t fallback)
{
    const size_t start = k->cells.n;
    double sum;
    cdc_status st = append_merged(k, distinct, &sum);
    if (st != CDC_OK) return st;
    if (!(sum > 0.0) && fallback >= 0) {
        k->cells.n = k->weights.n = start;
        if (cdc_ivec_push(&k->cells, fallback) || cdc_dvec_push(&k->weights, 1.0))
            return cdc_fail(k->ctx, CDC_ERR_NOMEM, "out of memory storing kernels");
        return CDC_OK;
    }
    if (!(sum > 0.0) || !isfinite(sum)) return no_weight(k, id);
    const double inv = 1.0 / sum;
    for (size_t q = start; q < k->cells.n; ++q) k->weights.v[q] *= inv;
    return CDC_OK;
}

static cdc_status record_outside(cdc_kernels *k, int64_t id)
{
    if ((size_t)k->n_outside == k->outside_cap) {
        const size_t cap = k->outside_cap ? 2 * k->outside_cap : 16;
        int64_t *v = realloc(k->outside_ids, cap * sizeof *v);
        if (!v) return cdc_fail(k->ctx, CDC_ERR_NOMEM, "out of memory listing particles outside");
        k->outside_ids = v;
        k->outside_cap = cap;
    }
    k->outside_ids[k->n_outside++] = id;
    return CDC_OK;
}

static double now_seconds(void)
{
    struct timespec ts; /* monotonic: immune to clock adjustments */
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The one kernel-build loop, serial and parallel. Serial (no ghosts): every kernel is whole on this
 * mesh and is normalised as it is made. Parallel: the local particles and the ghosts get raw
 * (merged, unnormalised) kernels over this rank's cells, their sums for the caller to add across
 * the ranks, and their fallback cell as an entry of weight 0 (cdc_kernels_normalise). */
static cdc_status build(cdc_kernels *k, const cdc_particles *local, const cdc_particles *ghosts)
{
    cdc_context *ctx = k->ctx;
    const int whole = ghosts == NULL;
    cdc_status st = check_particles(k, local, whole);
    if (st == CDC_OK && !whole) st = check_particles(k, ghosts, 0);
    if (st != CDC_OK) return st;
    const int32_t n = local->n + (whole ? 0 : ghosts->n);
    k->n = n;
    k->n_local = local->n;
    k->offsets.n = 1;
    k->cells.n = k->weights.n = 0;
    k->n_outside = 0;
    if (cdc_ivec_reserve(&k->offsets, (size_t)n + 1) || cdc_ivec_reserve(&k->hosts, (size_t)n + 1) ||
        (!whole && (cdc_dvec_reserve(&k->raw_sums, (size_t)n + 1) || cdc_ivec_reserve(&k->fallback_pos, (size_t)n + 1))))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory storing kernels");

    /* pass 1: host cells (timed apart from the kernels, for the solver's stage timers); a ghost's
     * centre is not in this mesh: its searches start from the nearest cell within its reach */
    const double t0 = now_seconds();
    for (int32_t i = 0; i < local->n; ++i) {
        const int32_t hint = local->host_hint ? local->host_hint[i] : -1;
        st = cdc_locate_point(ctx, local->position + 3 * (size_t)i, hint, &k->hosts.v[i]);
        if (st != CDC_OK) return st;
        if (local->host_hint) local->host_hint[i] = k->hosts.v[i];
    }
    for (int32_t g = 0; g < n - local->n; ++g) {
        const double reach = k->method->reach(&k->prm, ghosts->radius[g]) + ghosts->radius[g];
        st = cdc_nearest_cell(ctx, ghosts->position + 3 * (size_t)g, reach, &k->hosts.v[local->n + g]);
        if (st != CDC_OK) return st;
    }
    const double t1 = now_seconds();

    /* pass 2: kernels */
    cdc_kernel_builder b = {&k->raw_cells, &k->raw_weights, -1, 0, &k->cand};
    for (int32_t i = 0; i < n; ++i) {
        const int ghost = i >= local->n;
        const cdc_particles *p = ghost ? ghosts : local;
        const int32_t j = ghost ? i - local->n : i;
        const cdc_particle_in in = {{p->position[3 * (size_t)j], p->position[3 * (size_t)j + 1],
                                     p->position[3 * (size_t)j + 2]},
                                    p->radius[j], k->hosts.v[i], ghost};
        if (!whole) {
            k->raw_sums.v[i] = 0.0;
            k->fallback_pos.v[i] = -1;
        }
        if (in.host < 0) {
            if (!ghost && (st = record_outside(k, cdc_particle_id(p, j))) != CDC_OK) return st;
        } else {
            k->raw_cells.n = k->raw_weights.n = 0;
            b.fallback_cell = -1;
            b.distinct = 0;
            st = k->method->build(ctx, &k->prm, &in, &b);
            if (st != CDC_OK) return st;
            if (whole) {
                st = append_normalised(k, cdc_particle_id(p, j), b.distinct, b.fallback_cell);
            } else {
                st = append_merged(k, b.distinct, &k->raw_sums.v[i]);
                if (st == CDC_OK && b.fallback_cell >= 0) { /* weight 0 unless no rank has anything else */
                    k->fallback_pos.v[i] = (int32_t)k->cells.n;
                    if (cdc_ivec_push(&k->cells, b.fallback_cell) || cdc_dvec_push(&k->weights, 0.0))
                        st = cdc_fail(ctx, CDC_ERR_NOMEM, "out of memory storing kernels");
                }
            }
            if (st != CDC_OK) return st;
        }
        k->offsets.v[k->offsets.n++] = (int32_t)k->cells.n;
    }
    k->seconds_locate = t1 - t0;
    k->seconds_kernel = now_seconds() - t1;
    if (k->n_outside > 0) {
        char list[256] = "";
        size_t used = 0;
        for (int32_t q = 0; q < k->n_outside && q < 10 && used < sizeof list - 24; ++q)
            used += (size_t)snprintf(list + used, sizeof list - used, "%s%lld", q ? " " : "",
                                     (long long)k->outside_ids[q]);
        return cdc_fail(ctx, CDC_ERR_OUTSIDE, "%d particle(s) outside %s, ids: %s%s", (int)k->n_outside,
                        whole ? "the mesh" : "this rank's mesh", list, k->n_outside > 10 ? " ..." : "");
    }
    return CDC_OK;
}

cdc_status cdc_kernels_build(cdc_kernels *k, const cdc_particles *p)
{
    if (!k) return CDC_ERR_ARGUMENT;
    return build(k, p, NULL);
}

cdc_status cdc_kernels_build_raw(cdc_kernels *k, const cdc_particles *local, const cdc_particles *ghosts)
{
    if (!k || !local || !ghosts)
        return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT, "cdc_kernels_build_raw: NULL argument");
    return build(k, local, ghosts);
}

const double *cdc_kernels_raw_sums(const cdc_kernels *k) { return k ? k->raw_sums.v : NULL; }

cdc_status cdc_kernels_normalise(cdc_kernels *k, const double *global_sums, const int64_t *local_ids)
{
    if (!k || (!global_sums && k->n > 0)) return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT, "cdc_kernels_normalise: NULL argument");
    for (int32_t i = 0; i < k->n; ++i) {
        const double S = global_sums[i];
        const int32_t a = k->offsets.v[i], e = k->offsets.v[i + 1];
        if (S > 0.0 && isfinite(S)) {
            const double inv = 1.0 / S;
            for (int32_t q = a; q < e; ++q) k->weights.v[q] *= inv;
        } else if (k->fallback_pos.v[i] >= 0) {
            k->weights.v[k->fallback_pos.v[i]] = 1.0;
        } else if (i < k->n_local && e > a) {
            return no_weight(k, local_ids ? local_ids[i] : (int64_t)i);
        }
    }
    return CDC_OK;
}

double cdc_kernels_reach(const cdc_kernels *k, double radius)
{
    const double r = k->method->reach(&k->prm, radius);
    return r > radius ? r : radius;
}

int32_t cdc_kernels_count(const cdc_kernels *k) { return k ? k->n : 0; }

void cdc_kernels_timing(const cdc_kernels *k, double *seconds_locate, double *seconds_kernel)
{
    if (seconds_locate) *seconds_locate = k ? k->seconds_locate : 0.0;
    if (seconds_kernel) *seconds_kernel = k ? k->seconds_kernel : 0.0;
}
cdc_context *cdc_kernels_context(const cdc_kernels *k) { return k ? k->ctx : NULL; }
const int32_t *cdc_kernels_offsets(const cdc_kernels *k) { return k ? k->offsets.v : NULL; }
const int32_t *cdc_kernels_cells(const cdc_kernels *k) { return k ? k->cells.v : NULL; }
const double *cdc_kernels_weights(const cdc_kernels *k) { return k ? k->weights.v : NULL; }
const int32_t *cdc_kernels_hosts(const cdc_kernels *k) { return k ? k->hosts.v : NULL; }

int32_t cdc_kernels_outside(const cdc_kernels *k, const int64_t **ids)
{
    if (ids) *ids = k ? k->outside_ids : NULL;
    return k ? k->n_outside : 0;
}
