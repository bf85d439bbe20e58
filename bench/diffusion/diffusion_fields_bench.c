/*
 * diffusion_fields_bench.c -- smoothing k fields together (cdc_diffuse_fields) against one by one
 * (cdc_diffuse), on the meshes of the Mueller bed (tutorials/fluidizedBedMuller: 10 x 44 x 120 mm,
 * dx/d = 1 and 0.67 for d = 1.2 mm) with its bandwidth b = 6 d = 7.2 mm. This is the smoothing of
 * the fluid's sources with smoothExchangeFields (fFluid and Ksl: k = 4; explicit drag: fFluid, k = 3).
 *
 * The fields: a bed in the lower 30 % of the box (values drawn uniformly in [0.3, 0.6) per cell and
 * field, as alpha_p and the drag are rough at the scale of a cell), zero above. The two ways alternate,
 * each repeated; the medians are compared, so the ratio comes from one run on one machine state. Every
 * repetition checks that both give the same bits (else the run fails).
 *
 *   build/diffusion_fields_bench [-r REPS] [-o CSV]
 */
#include "../../src/core/coarse_dem.h"
#include "../../src/core/tools/box_mesh.h"
#include "../../src/core/tools/program_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void die(const char *what, const char *why)
{
    fprintf(stderr, "diffusion_fields_bench: %s: %s\n", what, why);
    exit(1);
}

int main(int argc, char **argv)
{
    int reps = 7;
    const char *csv = NULL;
    for (int i = 1; i < argc; ++i) {
        if (!strcmp(argv[i], "-r") && i + 1 < argc) reps = atoi(argv[++i]);
        else if (!strcmp(argv[i], "-o") && i + 1 < argc) csv = argv[++i];
        else {
            fprintf(stderr, "usage: diffusion_fields_bench [-r REPS] [-o CSV]\n");
            return 2;
        }
    }
    if (reps < 1 || reps > 1000) {
        fprintf(stderr, "diffusion_fields_bench: -r needs 1 to 1000 repetitions\n");
        return 2;
    }
    FILE *out = csv ? fopen(csv, "w") : NULL;
    if (csv && !out) die(csv, "cannot write");
    if (out) fprintf(out, "mesh,cells,fields,reps,alone_s,together_s,together_over_alone\n");
    printf("%-8s %8s %6s %5s %10s %12s %8s\n", "dx/d", "cells", "fields", "reps", "alone s", "together s", "ratio");

    static const uint8_t walls[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL,
                                     CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};
    const struct { const char *name; int nx, ny, nz; } meshes[2] = {{"1", 8, 36, 100}, {"0.67", 12, 54, 150}};
    const double lo[3] = {0, 0, 0}, hi[3] = {0.010, 0.044, 0.120};
    cdc_diffusion_params prm = {0};
    prm.bandwidth = 7.2e-3;
    for (int mi = 0; mi < 2; ++mi) {
        box_mesh b;
        if (box_mesh_create(&b, meshes[mi].nx, meshes[mi].ny, meshes[mi].nz, lo, hi, walls, 0.0) != 0)
            die("box_mesh_create", "failed");
        cdc_context *ctx = NULL;
        if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) die("cdc_context_create", cdc_create_error());
        const size_t nc = (size_t)b.mesh.n_cells;
        for (int k = 3; k <= 4; ++k) {
            double *fields = malloc(nc * (size_t)k * sizeof(double));
            double *alone = malloc(nc * (size_t)k * sizeof(double)), *together = malloc(nc * (size_t)k * sizeof(double));
            double *one = malloc(nc * sizeof(double));
            double *t_alone = malloc((size_t)reps * sizeof(double)), *t_together = malloc((size_t)reps * sizeof(double));
            if (!fields || !alone || !together || !one || !t_alone || !t_together) die("allocation", "out of memory");
            uint64_t seed = 2026;
            for (size_t c = 0; c < nc; ++c)
                for (int d = 0; d < k; ++d)
                    fields[c * (size_t)k + (size_t)d] =
                        b.mesh.cell_centres[3 * c + 2] < 0.3 * hi[2] ? 0.3 + 0.3 * program_uniform(&seed) : 0.0;
            for (int r = 0; r < reps; ++r) {
                double t0 = program_seconds();
                for (int d = 0; d < k; ++d) {
                    for (size_t c = 0; c < nc; ++c) one[c] = fields[c * (size_t)k + (size_t)d];
                    if (cdc_diffuse(ctx, &prm, one) != CDC_OK) die("cdc_diffuse", cdc_last_error(ctx));
                    for (size_t c = 0; c < nc; ++c) alone[c * (size_t)k + (size_t)d] = one[c];
                }
                t_alone[r] = program_seconds() - t0;
                memcpy(together, fields, nc * (size_t)k * sizeof(double));
                t0 = program_seconds();
                if (cdc_diffuse_fields(ctx, &prm, together, k) != CDC_OK) die("cdc_diffuse_fields", cdc_last_error(ctx));
                t_together[r] = program_seconds() - t0;
                if (memcmp(alone, together, nc * (size_t)k * sizeof(double)) != 0)
                    die("check", "the fields smoothed together differ from the same fields smoothed alone");
            }
            const double a = program_median(t_alone, reps), t = program_median(t_together, reps);
            printf("%-8s %8zu %6d %5d %10.4f %12.4f %8.3f\n", meshes[mi].name, nc, k, reps, a, t, t / a);
            if (out) fprintf(out, "%s,%zu,%d,%d,%.6f,%.6f,%.4f\n", meshes[mi].name, nc, k, reps, a, t, t / a);
            free(fields); free(alone); free(together); free(one); free(t_alone); free(t_together);
        }
        cdc_context_destroy(ctx);
        box_mesh_destroy(&b);
    }
    if (out) fclose(out);
    return 0;
}
