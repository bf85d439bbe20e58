/*
 * wall_mirror.c -- what the wall mirror adds to a bigParticle kernel build: the same particles'
 * kernels (n = 5) built with and without wallMirror, alternately, in one run.
 *
 * Why: the Mueller demo's kernel stage is its largest coupling stage, and a wall-mirrored kernel
 * first finds the walls in reach of the particle (cdc_wall_planes_near), then builds its images.
 * The ratio of the two builds, measured side by side, is the wall's share; comparing it between two
 * builds of the core says what a change to the wall search gained. The kernels' checksum says
 * whether the change left them bit for bit as they were.
 *
 * The Mueller tutorial's mesh (8 x 36 x 100 cells on 10 x 44 x 120 mm, every boundary a wall),
 * 9240 spheres of d = 1.2 mm at random in the lower 40 mm, in spatial order (by 1.25 mm bins, z
 * then y then x) as LIGGGHTS' atom sort keeps them. Usage:
 *     build/wall_mirror [ROUNDS]      (default 40 rounds of one build each way; medians printed)
 */
#include "../muller_bed.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define N_PARTICLES MULLER_N_PARTICLES
#define BIN 1.25e-3
#define MAX_ROUNDS 1001

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static int compare_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, compare_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static double bin_key(const double *x)
{
    return (floor(x[2] / BIN) * 1000.0 + floor(x[1] / BIN)) * 1000.0 + floor(x[0] / BIN);
}

static int compare_position(const void *a, const void *b)
{
    const double ka = bin_key(a), kb = bin_key(b);
    return (ka > kb) - (ka < kb);
}

/* FNV-1a over the kernels' cells and weights: equal sums, (almost surely) equal kernels */
static unsigned long long checksum(const cdc_kernels *k, int n)
{
    const int32_t *off = cdc_kernels_offsets(k), *cells = cdc_kernels_cells(k);
    const double *w = cdc_kernels_weights(k);
    unsigned long long h = 1469598103934665603ULL;
    for (int32_t e = 0; e < off[n]; ++e) {
        unsigned char bytes[12];
        memcpy(bytes, cells + e, 4);
        memcpy(bytes + 4, w + e, 8);
        for (int b = 0; b < 12; ++b) h = (h ^ bytes[b]) * 1099511628211ULL;
    }
    return h;
}

static int fail(cdc_context *ctx, const char *what)
{
    fprintf(stderr, "wall_mirror: %s: %s\n", what, ctx ? cdc_last_error(ctx) : cdc_create_error());
    return 1;
}

int main(int argc, char **argv)
{
    const int rounds = argc > 1 ? atoi(argv[1]) : 40;
    if (rounds < 1 || rounds > MAX_ROUNDS) {
        fprintf(stderr, "wall_mirror: ROUNDS must be 1..%d\n", MAX_ROUNDS);
        return 2;
    }
    box_mesh b;
    if (muller_mesh(&b)) return fail(NULL, "mesh");
    cdc_context *ctx;
    if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) return fail(NULL, "context");
    cdc_kernel_params mirrored = {0}, plain = {0};
    mirrored.expansion_factor = plain.expansion_factor = 5.0;
    mirrored.wall_mirror = 1;
    cdc_kernels *km, *kp;
    if (cdc_kernels_create(ctx, "bigParticle", &mirrored, &km) != CDC_OK ||
        cdc_kernels_create(ctx, "bigParticle", &plain, &kp) != CDC_OK)
        return fail(ctx, "kernels");

    static double x[3 * N_PARTICLES], r[N_PARTICLES];
    srand(1);
    for (int i = 0; i < N_PARTICLES; ++i) muller_place(x, r, i);
    qsort(x, N_PARTICLES, 3 * sizeof *x, compare_position);
    const cdc_particles p = {N_PARTICLES, x, r, NULL, NULL};
    /* the first builds locate the particles and make the candidate lists: not timed */
    if (cdc_kernels_build(km, &p) != CDC_OK || cdc_kernels_build(kp, &p) != CDC_OK) return fail(ctx, "build");
    static double tm[MAX_ROUNDS], tp[MAX_ROUNDS];
    for (int k = 0; k < rounds; ++k) {
        const double t0 = now();
        if (cdc_kernels_build(km, &p) != CDC_OK) return fail(ctx, "build");
        const double t1 = now();
        if (cdc_kernels_build(kp, &p) != CDC_OK) return fail(ctx, "build");
        tm[k] = t1 - t0;
        tp[k] = now() - t1;
    }
    const double m = median(tm, rounds), u = median(tp, rounds);
    printf("bigParticle n = 5, %d particles, %d rounds (medians): wall-mirrored %.3f us/particle, "
           "unmirrored %.3f us/particle, ratio %.3f; kernels' checksum %016llx\n",
           N_PARTICLES, rounds, 1e6 * m / N_PARTICLES, 1e6 * u / N_PARTICLES, m / u, checksum(km, N_PARTICLES));
    cdc_kernels_destroy(km);
    cdc_kernels_destroy(kp);
    cdc_context_destroy(ctx);
    box_mesh_destroy(&b);
    return 0;
}
