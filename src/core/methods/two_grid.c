/*
 * twoGrid -- simplified two-grid method (Deb & Tafti; simplified form of Zhang et al., Phys. Fluids
 * 35, 113330 (2023), §II.B): the cells whose centre lies within a search sphere of radius 3R
 * (search_factor) share the particle volume with a uniform volume fraction, found by the
 * cell-topology search from the host cell. Same body as bigParticle with n = search_factor;
 * kept as its own name because users know it under this one.
 */
#include "radial.h"

static const double default_search_factor = 3.0;

static double factor(const cdc_kernel_params *prm)
{
    return prm->search_factor > 0.0 ? prm->search_factor : default_search_factor;
}

static void defaults(cdc_kernel_params *prm)
{
    if (prm->search_factor == 0.0) prm->search_factor = default_search_factor;
}

static cdc_status check(cdc_context *ctx, const cdc_kernel_params *prm)
{
    if (prm->search_factor != 0.0 && !(prm->search_factor >= 1.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "twoGrid: searchFactor %g is invalid (must be >= 1)",
                        prm->search_factor);
    return CDC_OK;
}

static double reach(const cdc_kernel_params *prm, double r) { return factor(prm) * r; }

static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    const double radius = factor(prm) * p->r, r2 = radius * radius;
    return cdc_radial_kernel(ctx, p, radius, prm->wall_mirror, cdc_uniform_profile, &r2, out);
}

const cdc_method cdc_method_two_grid = {"twoGrid", CDC_PARAM_SEARCH_FACTOR | CDC_PARAM_WALL_MIRROR, check, reach, build,
                                        defaults};
