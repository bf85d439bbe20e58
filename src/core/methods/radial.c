/*
 * radial.c -- the shared body of the expansion kernels (bigParticle with n, twoGrid, gaussian):
 * cells whose centre lies within a search radius get the raw weight V_c * profile(|x_c - x|).
 *
 * Wall-aware option: the part of the kernel that would fall beyond a wall is mirrored back
 * (method of images), i.e. a cell gets V_c * sum over images x' of profile(|x_c - x'|). A faceted
 * curved wall is mirrored across its facet nearest to the particle (its tangent plane there), walls
 * meeting at sharp angles across each (cdc_nearest_wall_planes). Without it,
 * a particle near a wall has fewer cells to share its volume and the near-wall volume fraction
 * rises (Zhang et al. 2023, Fig. 10). With it, a uniform layer next to a wall stays flat.
 * Every image lies beyond the wall, so any in-domain cell it reaches is at least as close to the
 * particle itself: the flood fill over the original search radius already holds all such cells.
 */
#include "radial.h"

cdc_status cdc_radial_neighbourhood(cdc_context *ctx, const cdc_particle_in *p, double radius, int wall_mirror,
                                    cdc_candidates *search, double images[][3], int *n_images)
{
    cdc_plane planes[CDC_MAX_WALL_FACETS];
    int n_planes = 0;
    cdc_status st = cdc_cells_within(ctx, search, p->x, p->host, p->ghost, radius, &ctx->near_cells);
    if (st == CDC_OK && wall_mirror) st = cdc_wall_planes_near(ctx, p->x, radius, planes, &n_planes);
    if (st != CDC_OK) return st;
    n_planes = cdc_nearest_wall_planes(p->x, planes, n_planes);
    if (n_planes > CDC_MAX_PLANES)
        return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                        "wallMirror: more than %d walls meeting at sharp angles within %g m of the particle at "
                        "(%g %g %g)", CDC_MAX_PLANES, radius, p->x[0], p->x[1], p->x[2]);
    *n_images = cdc_mirror_images(p->x, planes, n_planes, radius, images);
    if (*n_images < 0)
        return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                        "wallMirror: more than %d mirror images of the particle at (%g %g %g) within %g m "
                        "(a domain thinner than the kernel)", CDC_MAX_IMAGES, p->x[0], p->x[1], p->x[2], radius);
    return CDC_OK;
}
