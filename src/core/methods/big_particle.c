/*
 * bigParticle -- big particle method (Zhang et al., Phys. Fluids 35, 113330 (2023), §II.E, Fig. 4).
 *
 * expansion_factor = 0, the original form: the particle volume is split in equal shares over the
 * cells its sphere overlaps (eq. 8), overlap tested against the cells' bounding boxes (exact for
 * box cells). expansion_factor = n >= 1, the paper's optimized form: the cells whose centre lies
 * within n R share the volume so that the volume fraction they get is uniform (the intent of eq. 9,
 * which is not dimensionally consistent as printed): w_c = V_c / sum V_c. When no cell centre is
 * within n R the kernel falls back to the centroid method. The paper recommends n = 4 or 5.
 */
#include "radial.h"

static cdc_status check(cdc_context *ctx, const cdc_kernel_params *prm)
{
    const double n = prm->expansion_factor;
    if (n != 0.0 && !(n >= 1.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                        "bigParticle: expansionFactor %g is invalid (must be >= 1, or 0 for the original "
                        "equal split)", n);
    return CDC_OK;
}

static double reach(const cdc_kernel_params *prm, double r)
{
    return prm->expansion_factor > 0.0 ? prm->expansion_factor * r : r;
}

static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    if (prm->expansion_factor > 0.0) {
        const double radius = prm->expansion_factor * p->r, r2 = radius * radius;
        return cdc_radial_kernel(ctx, p, radius, prm->wall_mirror, cdc_uniform_profile, &r2, out);
    }
    cdc_status st = cdc_cells_overlapping(ctx, p->x, p->host, p->ghost, p->r, &ctx->near_cells);
    if (st != CDC_OK) return st;
    for (size_t q = 0; q < ctx->near_cells.n; ++q)
        if (cdc_kernel_add(out, ctx->near_cells.v[q], 1.0))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "bigParticle: out of memory");
    return CDC_OK;
}

const cdc_method cdc_method_big_particle = {"bigParticle", CDC_PARAM_EXPANSION_FACTOR | CDC_PARAM_WALL_MIRROR, check, reach, build};
