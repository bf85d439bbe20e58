/*
 * diffusion_by_size.c -- size-aware diffusion smoothing for polydisperse beds.
 *
 * Zhang et al. (2023) note that diffusion smoothing uses one bandwidth b = 6 d for the whole bed,
 * which is wrong for a binary bed: the small particles get smeared over many of their own
 * diameters while the large ones may still be under-resolved. Here the smoothing length follows
 * particle size: particles are grouped into diameter classes of width `class_ratio` (geometric,
 * starting at the smallest diameter); each class's volume is spread with the given kernels,
 * diffused with its own bandwidth b_k = bandwidth_over_d * d_k (d_k = volume-weighted mean
 * diameter of the class) and the classes are summed. Diffusion is linear and conserving, so the
 * sum conserves the total solid volume; a monodisperse bed gives exactly cdc_diffuse's result.
 */
#include "internal.h"

#include <math.h>
#include <string.h>

#define CDC_MAX_CLASSES 64

cdc_status cdc_alpha_p_diffused_by_size(cdc_context *ctx, const cdc_kernels *k, const cdc_particles *p,
                                        double bandwidth_over_d, double class_ratio,
                                        const cdc_diffusion_params *base, double *alpha_p, int *n_classes)
{
    if (!ctx || !k || !p || !base || !alpha_p)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: NULL argument");
    if (!(bandwidth_over_d > 0.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: bandwidth/d %g is invalid (must be > 0)",
                        bandwidth_over_d);
    if (!(class_ratio > 1.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: class ratio %g is invalid (must be > 1)",
                        class_ratio);
    if (ctx->has_halo && !ctx->halo.max)
        return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                        "size-aware diffusion: across ranks it needs the halo's max callback (the classes start at "
                        "the smallest diameter of all ranks)");
    if (p->n != cdc_kernels_count(k))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: particle count differs from the kernels");
    const size_t nc = (size_t)ctx->mesh->n_cells, np = (size_t)p->n, n_own = (size_t)k->n_local;
    if (cdc_dvec_reserve(&ctx->class_q, np + 1) || cdc_dvec_reserve(&ctx->class_field, nc) ||
        cdc_dvec_reserve(&ctx->class_sum, nc))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "size-aware diffusion: out of memory");
    double *q = ctx->class_q.v, *field = ctx->class_field.v, *sum = ctx->class_sum.v;

    /* the smallest diameter of all ranks (a ghost's is its owner's: counting it changes nothing) */
    double dmin = INFINITY;
    for (size_t i = 0; i < np; ++i)
        if (!(p->radius[i] > 0.0))
            return cdc_fail(ctx, CDC_ERR_PARTICLE, "particle %lld: radius %g is invalid (must be > 0)",
                            (long long)cdc_particle_id(p, (int32_t)i), p->radius[i]);
        else if (2.0 * p->radius[i] < dmin)
            dmin = 2.0 * p->radius[i];
    if (ctx->has_halo) {
        double neg = -dmin;
        if (ctx->halo.max(ctx->halo.user, &neg, 1))
            return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: the global maximum failed");
        dmin = -neg;
    }

    /* class of each particle; each class's volume and volume-weighted diameter over the particles
     * each rank owns, summed over the ranks, with the count of particles beyond the last class
     * (so that every rank stops together) */
    double cls[2 * CDC_MAX_CLASSES + 1] = {0}, *vol = cls, *vd = cls + CDC_MAX_CLASSES;
    const double lr = log(class_ratio);
    for (size_t i = 0; i < n_own; ++i) {
        const int c = (int)floor(log(2.0 * p->radius[i] / dmin) / lr);
        if (c >= CDC_MAX_CLASSES) {
            cls[2 * CDC_MAX_CLASSES] += 1.0;
            continue;
        }
        const double v = 4.0 / 3.0 * CDC_PI * pow(p->radius[i], 3);
        vol[c] += v;
        vd[c] += v * 2.0 * p->radius[i];
    }
    if (ctx->has_halo && ctx->halo.sum(ctx->halo.user, cls, 2 * CDC_MAX_CLASSES + 1))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "size-aware diffusion: the global sum failed");
    if (cls[2 * CDC_MAX_CLASSES] > 0.0)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                        "size-aware diffusion: more than %d diameter classes; increase the class ratio",
                        CDC_MAX_CLASSES);
    int ncls = 0;
    for (int c = 0; c < CDC_MAX_CLASSES; ++c)
        if (vol[c] > 0.0) ncls = c + 1;

    memset(sum, 0, nc * sizeof *sum);
    int used = 0;
    for (int c = 0; c < ncls; ++c) {
        if (vol[c] <= 0.0) continue;
        ++used;
        for (size_t i = 0; i < np; ++i) {
            const int ci = (int)floor(log(2.0 * p->radius[i] / dmin) / lr);
            q[i] = ci == c ? 4.0 / 3.0 * CDC_PI * pow(p->radius[i], 3) : 0.0;
        }
        cdc_status st = cdc_spread(k, q, 1, field);
        if (st != CDC_OK) return st;
        cdc_diffusion_params prm = *base;
        prm.bandwidth = bandwidth_over_d * vd[c] / vol[c];
        prm.particle_diameter = vd[c] / vol[c];
        st = cdc_diffuse(ctx, &prm, field);
        if (st != CDC_OK) return st;
        for (size_t j = 0; j < nc; ++j) sum[j] += field[j];
    }
    memcpy(alpha_p, sum, nc * sizeof *alpha_p);
    if (n_classes) *n_classes = used;
    return CDC_OK;
}
