/* radial.h -- shared body of the expansion kernels; see radial.c. */
#ifndef CDC_RADIAL_H
#define CDC_RADIAL_H
#include "../internal.h"

cdc_status cdc_radial_kernel(cdc_context *ctx, const cdc_particle_in *p, double radius, int wall_mirror,
                             double (*profile)(double d2, const void *arg), const void *arg,
                             cdc_kernel_builder *out);

/* Uniform profile: 1 inside the sphere of radius sqrt(*(double*)arg2), 0 outside. */
static inline double cdc_uniform_profile(double d2, const void *radius2)
{
    return d2 <= *(const double *)radius2 * CDC_RADIUS_SLACK ? 1.0 : 0.0;
}
#endif
