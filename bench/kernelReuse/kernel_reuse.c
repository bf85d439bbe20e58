/*
 * kernel_reuse.c -- how many kernels an exact reuse could skip: the share of particles whose
 * bigParticle kernel (n = 5, wallMirror) is bit-identical after one CFD step of motion.
 *
 * Why: the bigParticle weights w_c = V_c / sum V_c over the cells whose centre lies within nR are
 * piecewise constant in the particle's position, so a kernel could be kept while no cell centre
 * (of the particle or of its mirror images) crosses the sphere. The kernel stage is the largest
 * coupling stage of the Mueller demo (bench/cases/README.md); this bounds what skipping unchanged
 * kernels could save before anyone builds it.
 *
 * The Mueller tutorial's mesh (8 x 36 x 100 cells on 10 x 44 x 120 mm, every boundary a mirror
 * wall), 9240 spheres of d = 1.2 mm placed at random in the lower 40 mm, each moved by v dt with v
 * drawn from an isotropic normal distribution of the given rms speed. Usage:
 *     build/kernel_reuse [V_RMS_M_PER_S ...]     (default 0.05 0.15 0.3; dt 1.8e-4 s, the CFD step)
 */
#include "../../src/core/tools/box_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define N_PARTICLES 9240
#define DT 1.8e-4
#define RADIUS 0.6e-3

static double uniform(void) { return (rand() + 0.5) / ((double)RAND_MAX + 1.0); }
static double normal(void) { return sqrt(-2.0 * log(uniform())) * cos(6.283185307179586 * uniform()); }

/* 1 when particle i's kernel holds the same cells with the same weights in a and b */
static int same_kernel(const cdc_kernels *a, const cdc_kernels *b, int i)
{
    const int32_t *oa = cdc_kernels_offsets(a), *ob = cdc_kernels_offsets(b);
    const int32_t *ca = cdc_kernels_cells(a), *cb = cdc_kernels_cells(b);
    const double *wa = cdc_kernels_weights(a), *wb = cdc_kernels_weights(b);
    if (oa[i + 1] - oa[i] != ob[i + 1] - ob[i]) return 0;
    for (int32_t q = 0; q < oa[i + 1] - oa[i]; ++q)
        if (ca[oa[i] + q] != cb[ob[i] + q] || wa[oa[i] + q] != wb[ob[i] + q]) return 0;
    return 1;
}

static int fail(cdc_context *ctx, const char *what)
{
    fprintf(stderr, "kernel_reuse: %s: %s\n", what, ctx ? cdc_last_error(ctx) : cdc_create_error());
    return 1;
}

int main(int argc, char **argv)
{
    const double lo[3] = {0.0, 0.0, 0.0}, hi[3] = {0.010, 0.044, 0.120};
    const uint8_t walls[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};
    box_mesh b;
    if (box_mesh_create(&b, 8, 36, 100, lo, hi, walls, 0.0)) return fail(NULL, "mesh");
    cdc_context *ctx;
    if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) return fail(NULL, "context");
    cdc_kernel_params prm = {0};
    prm.expansion_factor = 5.0;
    prm.wall_mirror = 1;
    cdc_kernels *before, *after;
    if (cdc_kernels_create(ctx, "bigParticle", &prm, &before) != CDC_OK ||
        cdc_kernels_create(ctx, "bigParticle", &prm, &after) != CDC_OK)
        return fail(ctx, "kernels");

    static double x0[3 * N_PARTICLES], x1[3 * N_PARTICLES], r[N_PARTICLES];
    static const double default_speeds[] = {0.05, 0.15, 0.3};
    const int n_speeds = argc > 1 ? argc - 1 : 3;
    printf("v_rms (m/s) | kernels identical after one step of %g s | entries per kernel\n", DT);
    for (int s = 0; s < n_speeds; ++s) {
        const double v_rms = argc > 1 ? atof(argv[s + 1]) : default_speeds[s];
        srand(1);
        for (int i = 0; i < N_PARTICLES; ++i) {
            r[i] = RADIUS;
            x0[3 * i] = RADIUS + uniform() * (hi[0] - 2 * RADIUS);
            x0[3 * i + 1] = RADIUS + uniform() * (hi[1] - 2 * RADIUS);
            x0[3 * i + 2] = RADIUS + uniform() * 0.040;
            for (int d = 0; d < 3; ++d) x1[3 * i + d] = x0[3 * i + d] + v_rms / sqrt(3.0) * DT * normal();
        }
        const cdc_particles p0 = {N_PARTICLES, x0, r, NULL, NULL}, p1 = {N_PARTICLES, x1, r, NULL, NULL};
        if (cdc_kernels_build(before, &p0) != CDC_OK || cdc_kernels_build(after, &p1) != CDC_OK)
            return fail(ctx, "build");
        int same = 0;
        for (int i = 0; i < N_PARTICLES; ++i) same += same_kernel(before, after, i);
        printf("%g | %.1f %% | %.1f\n", v_rms, 100.0 * same / N_PARTICLES,
               (double)cdc_kernels_offsets(before)[N_PARTICLES] / N_PARTICLES);
    }
    cdc_kernels_destroy(before);
    cdc_kernels_destroy(after);
    cdc_context_destroy(ctx);
    box_mesh_destroy(&b);
    return 0;
}
