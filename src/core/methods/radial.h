/* radial.h -- shared body of the expansion kernels; see radial.c. */
#ifndef CDC_RADIAL_H
#define CDC_RADIAL_H
#include "../internal.h"

/* The cells within `radius` of the particle (in ctx->near_cells) and the particle's mirror images
 * (the particle itself first; only itself without wall_mirror). Returns the status. */
cdc_status cdc_radial_neighbourhood(cdc_context *ctx, const cdc_particle_in *p, double radius, int wall_mirror,
                                    cdc_candidates *search, double images[][3], int *n_images);

/* The radial kernel: raw weight V_c * sum over images of profile(|x_c - image|^2) on the cells of the
 * neighbourhood. Inline, so each method's profile is inlined into the loop over its cells (an
 * indirect call per cell was a tenth of a gaussian build). */
static inline cdc_status cdc_radial_kernel(cdc_context *ctx, const cdc_particle_in *p, double radius,
                                           int wall_mirror, double (*profile)(double d2, const void *arg),
                                           const void *arg, cdc_kernel_builder *out)
{
    double images[CDC_MAX_IMAGES][3];
    int n_images = 0;
    cdc_status st = cdc_radial_neighbourhood(ctx, p, radius, wall_mirror, out->search, images, &n_images);
    if (st != CDC_OK) return st;
    const size_t n = ctx->near_cells.n;
    if (cdc_ivec_reserve(out->cells, out->cells->n + n + 1) || cdc_dvec_reserve(out->weights, out->weights->n + n + 1))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "kernel: out of memory");
    /* local output cursors: through out-> the compiler must reload the counts after every store */
    int32_t *cells = out->cells->v + out->cells->n;
    double *weights = out->weights->v + out->weights->n;
    size_t taken = 0;
    for (size_t q = 0; q < n; ++q) {
        const int32_t c = ctx->near_cells.v[q];
        const double *xv = ctx->cell_xv + 4 * (size_t)c; /* centre, then volume */
        double w = profile(cdc_dist2(xv, images[0]), arg);
        for (int k = 1; k < n_images; ++k) w += profile(cdc_dist2(xv, images[k]), arg);
        if (w <= 0.0) continue;
        cells[taken] = c;
        weights[taken++] = w * xv[3];
    }
    out->cells->n += taken;
    out->weights->n += taken;
    out->distinct = 1; /* each cell of the neighbourhood once */
    /* No cell centre inside the search sphere (a particle much smaller than its cell): the
     * kernel falls back to the particle centroid method. In parallel this is decided when the
     * ranks' sums are known, so the method only names the cell. */
    if (!p->ghost) out->fallback_cell = p->host;
    return CDC_OK;
}

/* Uniform profile: 1 inside the sphere of radius sqrt(*(double*)arg2), 0 outside. */
static inline double cdc_uniform_profile(double d2, const void *radius2)
{
    return d2 <= *(const double *)radius2 * CDC_RADIUS_SLACK ? 1.0 : 0.0;
}
#endif
