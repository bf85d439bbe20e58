/*
 * kernel_bench.c -- micro-benchmark of the core's kernel methods: time per particle of the kernel
 * build and of alpha_p spreading, each as a ratio to a "touch-only" loop over the same kernel.
 *
 * Setup per particle count N: a cube of n^3 box cells with dx = d = 1 mm, n = round(cbrt(N pi/6 / 0.3))
 * so the mean alpha_p is ~0.3; N particles of diameter d at uniform random positions (fully inside,
 * overlaps allowed, fixed seed, in random memory order: no spatial sorting); all boundary faces walls.
 *
 * For each method:
 *   first   the first cdc_kernels_build: no host hints (every particle located through the spatial
 *           bins), fresh kernel buffers -- the first coupling step. It fills the host hints.
 *   build   cdc_kernels_build again, hints valid (the steady state: particles move less than a cell
 *           per coupling step), buffers at capacity; cdc_kernels_timing gives the locate share
 *   alpha   cdc_alpha_p from those kernels (zero the cell field, spread, divide by V_c)
 *   touch   the irreducible use of the same kernel: for every particle and every (cell, weight) of
 *           its kernel, acc[cell] += weight * V_p, into a cell array zeroed beforehand (the zeroing,
 *           a per-cell cost, is timed apart: zero_cells_s). Its result is checked against
 *           alpha_p * V_c, so it cannot be optimised away and the kernels are right.
 *           cdc_alpha_p's time includes its per-cell passes (zero, divide by V_c), so alpha/touch is
 *           its whole overhead over the bare kernel use.
 * Ratios build/touch, alpha/touch and first/touch come from the same run on the same kernels.
 * Short timings are repeated (median; >= 0.3 s of builds, >= 0.2 s of alpha + touch, >= 3 times).
 *
 * exact (~200 us/particle) and gaussian with b = 3d (~800 cells per kernel) are timed on the first
 * CAP_EXACT / CAP_GAUSSIAN particles of the set (same mesh) when N is larger, so that the 1e6 case
 * stays within the time and memory budget; the n_timed column says so.
 *
 * Usage: kernel_bench [-o results/kernels.csv] [-n 1000,10000,100000,1000000]
 */
#include "../src/core/coarse_dem.h"
#include "../src/core/tools/box_mesh.h"
#include "../src/core/tools/program_util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846
static const double D = 1e-3;
/* particles timed at most for the slow methods (the first ones of the set, same mesh) */
static const int CAP_GAUSSIAN = 20000, CAP_EXACT = 10000;

static void die(const char *what, const char *msg)
{
    fprintf(stderr, "kernel_bench: %s: %s\n", what, msg ? msg : "");
    exit(1);
}

static uint64_t rng_state = 12345;
static double rnd(void)
{
    return program_uniform(&rng_state);
}

typedef struct {
    const char *name;
    const char *core;
    cdc_kernel_params prm;
    int cap; /* 0: all particles */
} method_def;

/* The touch-only loop: accumulate weight * particle volume into a cell array zeroed beforehand
 * (the zeroing is a per-cell cost, timed apart; cdc_alpha_p's own per-cell passes are in its time). */
static void touch(const int32_t *off, const int32_t *cells, const double *w, const double *vol, int32_t np,
                  double *acc)
{
    for (int32_t i = 0; i < np; ++i) {
        const double v = vol[i];
        for (int32_t e = off[i]; e < off[i + 1]; ++e) acc[cells[e]] += w[e] * v;
    }
}

#define MAX_REPS 51

int main(int argc, char **argv)
{
    const char *out = "results/kernels.csv";
    const char *list = "1000,10000,100000,1000000";
    const char *only = NULL; /* -m: time one method (by its bench name), e.g. under perf */
    for (int a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "-o") && a + 1 < argc) out = argv[++a];
        else if (!strcmp(argv[a], "-n") && a + 1 < argc) list = argv[++a];
        else if (!strcmp(argv[a], "-m") && a + 1 < argc) only = argv[++a];
        else {
            fprintf(stderr, "usage: %s [-o CSV] [-n N1,N2,...] [-m METHOD]\n", argv[0]);
            return 2;
        }
    }
    method_def methods[6];
    memset(methods, 0, sizeof methods);
    methods[0].name = "centre";
    methods[1].name = "divided";
    methods[2].name = "bigParticle_n5";
    methods[2].core = "bigParticle";
    methods[2].prm.expansion_factor = 5;
    methods[3].name = "twoGrid";
    methods[3].prm.search_factor = 3;
    methods[4].name = "gaussian_b3d";
    methods[4].core = "gaussian";
    methods[4].prm.bandwidth = 3 * D;
    methods[4].cap = CAP_GAUSSIAN;
    methods[5].name = "exact";
    methods[5].cap = CAP_EXACT;
    for (int m = 0; m < 6; ++m)
        if (!methods[m].core) methods[m].core = methods[m].name;
    if (only) { /* a method not in the list would time nothing and look like a finished run */
        int known = 0;
        for (int m = 0; m < 6; ++m) known |= !strcmp(only, methods[m].name);
        if (!known) {
            fprintf(stderr, "kernel_bench: -m %s: unknown method (known:", only);
            for (int m = 0; m < 6; ++m) fprintf(stderr, " %s", methods[m].name);
            fprintf(stderr, ")\n");
            return 2;
        }
    }
    /* -n, parsed and checked once, before the CSV is overwritten: at most one count per comma + 1 */
    int n_counts = 0;
    long *counts = malloc(sizeof(long) * (strlen(list) / 2 + 1));
    if (!counts) die("allocation", "out of memory");
    for (const char *s = list; *s;) {
        char *end;
        const double N = strtod(s, &end);
        if (end == s || !(N >= 1 && N <= 1e8) || (*end && *end != ',')) {
            fprintf(stderr, "kernel_bench: -n %s: particle counts 1..1e8 separated by commas\n", list);
            return 2;
        }
        counts[n_counts++] = (long)N;
        s = *end == ',' ? end + 1 : end;
    }
    FILE *csv = fopen(out, "w");
    if (!csv) die(out, strerror(errno));
    fprintf(csv, "n_particles,n_cells,method,n_timed,cells_per_kernel,reps,build_s_per_particle,"
                 "locate_s_per_particle,alpha_s_per_particle,touch_s_per_particle,build_over_touch,"
                 "alpha_over_touch,first_build_s_per_particle,first_locate_s_per_particle,first_build_over_touch,"
                 "zero_cells_s,touch_check_rel_err\n");

    static const uint8_t walls[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL,
                                     CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};
    const double t_all = program_seconds();
    printf("%9s %9s %-15s %8s %8s %5s %11s %11s %11s %9s %9s %7s %10s %7s\n", "N", "cells", "method", "timed",
           "cells/k", "reps", "build s/p", "alpha s/p", "touch s/p", "build/tch", "alpha/tch", "locate%",
           "first/tch", "locate%");

    for (int k = 0; k < n_counts; ++k) {
        const long N = counts[k];
        const int n = (int)lround(cbrt(N * (PI / 6.0) / 0.3));
        const double L = n * D;
        box_mesh b;
        const double lo[3] = {0, 0, 0}, hi[3] = {L, L, L};
        if (box_mesh_create(&b, n, n, n, lo, hi, walls, 0.0) != 0) die("box_mesh_create", "failed");
        cdc_context *ctx = NULL;
        if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) die("cdc_context_create", cdc_create_error());
        {
            const double p0[3] = {0.5 * L, 0.5 * L, 0.5 * L};
            int32_t c;
            if (cdc_locate_point(ctx, p0, -1, &c) != CDC_OK) die("locate", cdc_last_error(ctx)); /* builds bins */
        }
        const int32_t nc = b.mesh.n_cells;
        double *pos = malloc(3 * sizeof(double) * (size_t)N), *rad = malloc(sizeof(double) * (size_t)N);
        double *vol = malloc(sizeof(double) * (size_t)N);
        int32_t *hints = malloc(sizeof(int32_t) * (size_t)N);
        double *alpha = malloc(sizeof(double) * (size_t)nc), *acc = malloc(sizeof(double) * (size_t)nc);
        if (!pos || !rad || !vol || !hints || !alpha || !acc) die("allocation", "out of memory");
        const double R = 0.5 * D;
        for (long i = 0; i < N; ++i) {
            for (int a = 0; a < 3; ++a) pos[3 * i + a] = R + (L - 2 * R) * rnd();
            rad[i] = R;
            vol[i] = 4.0 / 3.0 * PI * R * R * R;
        }

        for (int m = 0; m < 6; ++m) {
            const method_def *md = methods + m;
            if (only && strcmp(only, md->name)) continue;
            const int32_t nt = (int32_t)(md->cap && N > md->cap ? md->cap : N);
            cdc_particles p = {nt, pos, rad, NULL, hints};
            cdc_kernels *k = NULL;
            if (cdc_kernels_create(ctx, md->core, &md->prm, &k) != CDC_OK) die(md->name, cdc_last_error(ctx));

            /* first build: no hints (every particle located from scratch through the spatial bins)
             * and fresh buffers -- the first coupling step. It fills the host hints. */
            for (int32_t i = 0; i < nt; ++i) hints[i] = -1;
            double tb[MAX_REPS], tlv[MAX_REPS], tk, tl_first;
            double t0 = program_seconds();
            if (cdc_kernels_build(k, &p) != CDC_OK) die(md->name, cdc_last_error(ctx));
            const double first = program_seconds() - t0;
            cdc_kernels_timing(k, &tl_first, &tk);
            /* steady state: particles still in the hinted cells (they move less than a cell per
             * coupling step), buffers at capacity; repeated for >= 0.3 s in all, median */
            int reps = (int)ceil(0.3 / (first > 1e-9 ? first : 1e-9));
            reps = reps < 1 ? 1 : reps > MAX_REPS ? MAX_REPS : reps;
            for (int r = 0; r < reps; ++r) {
                t0 = program_seconds();
                if (cdc_kernels_build(k, &p) != CDC_OK) die(md->name, cdc_last_error(ctx));
                tb[r] = program_seconds() - t0;
                cdc_kernels_timing(k, &tlv[r], &tk);
            }
            const double tl_sum = program_median(tlv, reps); /* locate time, median */
            const double t_build = program_median(tb, reps);
            const int32_t *off = cdc_kernels_offsets(k), *cells = cdc_kernels_cells(k);
            const double *w = cdc_kernels_weights(k);
            const double cpk = (double)off[nt] / nt;

            /* alpha_p and touch-only: enough repetitions for >= 0.1 s each, at least 3, median */
            double ta[MAX_REPS], tt[MAX_REPS], tz[MAX_REPS];
            t0 = program_seconds();
            if (cdc_alpha_p(k, &p, alpha) != CDC_OK) die(md->name, cdc_last_error(ctx));
            memset(acc, 0, (size_t)nc * sizeof *acc);
            touch(off, cells, w, vol, nt, acc);
            const double pair = program_seconds() - t0;
            int reps2 = (int)ceil(0.2 / (pair > 1e-9 ? pair : 1e-9));
            reps2 = reps2 < 3 ? 3 : reps2 > MAX_REPS ? MAX_REPS : reps2;
            for (int r = 0; r < reps2; ++r) {
                t0 = program_seconds();
                if (cdc_alpha_p(k, &p, alpha) != CDC_OK) die(md->name, cdc_last_error(ctx));
                ta[r] = program_seconds() - t0;
                t0 = program_seconds();
                memset(acc, 0, (size_t)nc * sizeof *acc);
                const double t1 = program_seconds();
                touch(off, cells, w, vol, nt, acc);
                tt[r] = program_seconds() - t1;
                tz[r] = t1 - t0;
            }
            const double t_alpha = program_median(ta, reps2), t_touch = program_median(tt, reps2), t_zero = program_median(tz, reps2);

            /* the touch loop computed alpha_p * V_c */
            double err = 0.0, tot = 0.0;
            for (int32_t c = 0; c < nc; ++c) {
                err += fabs(acc[c] - alpha[c] * b.mesh.cell_volumes[c]);
                tot += acc[c];
            }
            const double rel = err / tot;
            if (!(rel < 1e-12)) die(md->name, "touch-only result differs from alpha_p * V_c");

            fprintf(csv, "%ld,%d,%s,%d,%.2f,%d,%.4e,%.4e,%.4e,%.4e,%.3f,%.3f,%.4e,%.4e,%.3f,%.4e,%.1e\n", N, nc,
                    md->name, nt, cpk, reps, t_build / nt, tl_sum / nt, t_alpha / nt, t_touch / nt, t_build / t_touch,
                    t_alpha / t_touch, first / nt, tl_first / nt, first / t_touch, t_zero, rel);
            fflush(csv);
            printf("%9ld %9d %-15s %8d %8.1f %5d %11.3e %11.3e %11.3e %9.1f %9.2f %6.0f%% %10.1f %6.0f%%\n", N, nc,
                   md->name, nt, cpk, reps, t_build / nt, t_alpha / nt, t_touch / nt, t_build / t_touch,
                   t_alpha / t_touch, 100.0 * tl_sum / t_build, first / t_touch, 100.0 * tl_first / first);
            fflush(stdout);
            cdc_kernels_destroy(k);
        }
        free(pos);
        free(rad);
        free(vol);
        free(hints);
        free(alpha);
        free(acc);
        cdc_context_destroy(ctx);
        box_mesh_destroy(&b);
    }
    fclose(csv);
    free(counts);
    printf("total %.1f s; results in %s\n", program_seconds() - t_all, out);
    return 0;
}
