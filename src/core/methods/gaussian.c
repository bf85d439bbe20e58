/*
 * gaussian -- statistical kernel method (Zhang et al., Phys. Fluids 35, 113330 (2023), §II.C,
 * eq. 6): raw weight V_c exp(-|x_c - x|^2 / b^2) over the cells whose centre lies within
 * cutoff_factor * b, then renormalised so the particle volume is conserved exactly (the
 * truncated Gaussian does not integrate to one on a finite mesh, nor near walls).
 */
#include "radial.h"

#include <math.h>

static const double default_cutoff_factor = 2.0;

static double cutoff(const cdc_kernel_params *prm)
{
    return prm->cutoff_factor > 0.0 ? prm->cutoff_factor : default_cutoff_factor;
}

static void defaults(cdc_kernel_params *prm)
{
    if (prm->cutoff_factor == 0.0) prm->cutoff_factor = default_cutoff_factor;
}

static cdc_status check(cdc_context *ctx, const cdc_kernel_params *prm)
{
    if (!(prm->bandwidth > 0.0) || !isfinite(prm->bandwidth))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "gaussian: bandwidth %g is invalid (must be > 0)", prm->bandwidth);
    if (prm->cutoff_factor != 0.0 && !(prm->cutoff_factor > 0.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "gaussian: cutoffFactor %g is invalid (must be > 0)",
                        prm->cutoff_factor);
    return CDC_OK;
}

static double reach(const cdc_kernel_params *prm, double r)
{
    (void)r;
    return cutoff(prm) * prm->bandwidth;
}

typedef struct { double inv_b2, cut2; } gauss_arg;

static double profile(double d2, const void *arg)
{
    const gauss_arg *g = arg;
    return d2 <= g->cut2 * CDC_RADIUS_SLACK ? exp(-d2 * g->inv_b2) : 0.0;
}

static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    const double radius = cutoff(prm) * prm->bandwidth;
    const gauss_arg g = {1.0 / (prm->bandwidth * prm->bandwidth), radius * radius};
    return cdc_radial_kernel(ctx, p, radius, prm->wall_mirror, profile, &g, out);
}

const cdc_method cdc_method_gaussian = {"gaussian", CDC_PARAM_BANDWIDTH | CDC_PARAM_CUTOFF_FACTOR | CDC_PARAM_WALL_MIRROR, check,
                                        reach, build, defaults};
