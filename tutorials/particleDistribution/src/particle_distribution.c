/*
 * particle_distribution.c -- the particle distribution case of Zhang et al., Phys. Fluids 35, 113330
 * (2023), section V.A (Figs. 6-9, Table I), run through the C core of this project.
 *
 * Domain 160d x 160d x 4d (centred on x = y = 0, z from 0 to 4d), all six boundaries walls.
 * Particles (d = 1 mm) are placed by random sequential addition (fixed seed, no overlap, fully
 * inside) in the central 60d x 60d x 4d at a mean volume fraction of 0.3, N = 86400 * 0.3 / pi
 * (eq. 23). Every volume fraction method is evaluated on meshes M1-M4 (Table I).
 *
 * Output (in the output directory, default "results"):
 *   summary.csv                         one row per (method, mesh)
 *   profile_<method>[_n<k>]_M<j>.csv     alpha_p along the row of cells nearest y = 0
 *   histogram_M2.csv                    alpha_p histograms at dx/d = 1 (Zhang et al. 2023 Fig. 8)
 *   field_<method>[_n<k>]_M2.csv        the mid-z layer of alpha_p at dx/d = 1 (Zhang et al. 2023 Fig. 6)
 *   particles.csv                       the particle centres (units of d)
 *
 * Usage: particle_distribution [-o DIR] [-m MESHES] [-s SEED] [-w]
 *   -m 1234  meshes to run (digits 1-4, default all), -s SEED (default 20231113)
 *   -w       wall-mirrored expansion kernels (bigParticle n, twoGrid, gaussian); default off, as in
 *            Zhang et al. 2023 (CFDEM's kernels are truncated at walls)
 */
#include "../../../src/core/coarse_dem.h"
#include "../../../src/core/tools/box_mesh.h"
#include "../../../src/core/tools/program_util.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#define PI 3.14159265358979323846

static const double D = 1e-3;            /* particle diameter (m) */
static const double HALF_DOMAIN = 80.0;  /* domain half width in x and y (units of d) */
static const double THICKNESS = 4.0;     /* domain thickness (units of d) */
static const double HALF_REGION = 30.0;  /* particle region half width (units of d) */
static const double STATS_HALF = 20.0;   /* statistics: cells with |x|, |y| <= 20 d */
static const double ALPHA_MEAN = 0.3;

/* ------------------------------------------------------------------ utilities */

static void die(const char *what, const char *msg)
{
    fprintf(stderr, "particle_distribution: %s: %s\n", what, msg ? msg : "");
    exit(1);
}

static FILE *open_out(const char *dir, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "w");
    if (!f) die(path, strerror(errno));
    return f;
}

/* splitmix64: small, fixed-seed, reproducible on every platform */
static uint64_t rng_state;
static double rnd(void)
{
    return program_uniform(&rng_state);
}

/* ------------------------------------------------------------------ particle placement */

/* Random sequential addition in units of d: centres uniform in the region shrunk by R, a candidate
 * is rejected if it is closer than d to any placed centre (cell list of cell size d). */
static long place_particles(int n, double *x)
{
    const double R = 0.5;
    enum { NCX = 60, NCY = 60, NCZ = 4 };
    int *head = malloc(sizeof(int) * NCX * NCY * NCZ), *next = malloc(sizeof(int) * (size_t)n);
    if (!head || !next) die("placement", "out of memory");
    for (int c = 0; c < NCX * NCY * NCZ; ++c) head[c] = -1;
    const long max_attempts = 200000000L;
    long attempts = 0;
    int placed = 0;
    while (placed < n) {
        if (++attempts > max_attempts) die("placement", "random sequential addition did not reach the target");
        const double p[3] = {-HALF_REGION + R + (2 * HALF_REGION - 2 * R) * rnd(),
                             -HALF_REGION + R + (2 * HALF_REGION - 2 * R) * rnd(), R + (THICKNESS - 2 * R) * rnd()};
        int ci[3] = {(int)(p[0] + HALF_REGION), (int)(p[1] + HALF_REGION), (int)p[2]};
        const int nmax[3] = {NCX, NCY, NCZ};
        for (int a = 0; a < 3; ++a) ci[a] = ci[a] < 0 ? 0 : ci[a] >= nmax[a] ? nmax[a] - 1 : ci[a];
        int ok = 1;
        for (int dk = -1; dk <= 1 && ok; ++dk)
            for (int dj = -1; dj <= 1 && ok; ++dj)
                for (int di = -1; di <= 1 && ok; ++di) {
                    const int i = ci[0] + di, j = ci[1] + dj, k = ci[2] + dk;
                    if (i < 0 || j < 0 || k < 0 || i >= NCX || j >= NCY || k >= NCZ) continue;
                    for (int q = head[(k * NCY + j) * NCX + i]; q >= 0; q = next[q]) {
                        const double dx = x[3 * q] - p[0], dy = x[3 * q + 1] - p[1], dz = x[3 * q + 2] - p[2];
                        if (dx * dx + dy * dy + dz * dz < 1.0) {
                            ok = 0;
                            break;
                        }
                    }
                }
        if (!ok) continue;
        const int c = (ci[2] * NCY + ci[1]) * NCX + ci[0];
        for (int a = 0; a < 3; ++a) x[3 * placed + a] = p[a];
        next[placed] = head[c];
        head[c] = placed++;
    }
    free(head);
    free(next);
    return attempts;
}

/* ------------------------------------------------------------------ the cases */

typedef struct {
    const char *name;   /* name in the CSV */
    const char *core;   /* core kernel method */
    int n_expand;       /* bigParticle expansion factor (0: original) */
    int diffuse;        /* 1: cdc_diffuse with b = 6d after the kernel */
} run_def;

static const run_def RUNS[] = {
    {"centre", "centre", 0, 0},          {"divided", "divided", 0, 0},
    {"bigParticle", "bigParticle", 0, 0}, {"bigParticle", "bigParticle", 2, 0},
    {"bigParticle", "bigParticle", 3, 0}, {"bigParticle", "bigParticle", 4, 0},
    {"bigParticle", "bigParticle", 5, 0}, {"twoGrid", "twoGrid", 0, 0},
    {"gaussian", "gaussian", 0, 0},       {"exact", "exact", 0, 0},
    {"diffusion", "centre", 0, 1},        {"dividedDiffusion", "divided", 0, 1},
};
enum { N_RUNS = sizeof RUNS / sizeof RUNS[0] };

static const double GAUSS_B = 3.0;     /* gaussian bandwidth (units of d), default cutoff 2 b */
static const double DIFFUSION_B = 6.0; /* diffusion bandwidth (units of d), default steps */
static const double TWO_GRID_SEARCH = 3.0;

typedef struct { int nx, ny, nz; } mesh_def;
static const mesh_def MESHES[4] = {{80, 80, 2}, {160, 160, 4}, {239, 239, 6}, {320, 320, 8}};

static void tag(const run_def *r, char *buf, size_t len)
{
    if (r->n_expand > 0) snprintf(buf, len, "%s_n%d", r->name, r->n_expand);
    else snprintf(buf, len, "%s", r->name);
}

int main(int argc, char **argv)
{
    const char *outdir = "results";
    const char *mesh_list = "1234";
    uint64_t seed = 20231113;
    int wall_mirror = 0;
    for (int a = 1; a < argc; ++a) {
        if (!strcmp(argv[a], "-o") && a + 1 < argc) outdir = argv[++a];
        else if (!strcmp(argv[a], "-m") && a + 1 < argc) mesh_list = argv[++a];
        else if (!strcmp(argv[a], "-s") && a + 1 < argc) seed = strtoull(argv[++a], NULL, 10);
        else if (!strcmp(argv[a], "-w")) wall_mirror = 1;
        else {
            fprintf(stderr, "usage: %s [-o DIR] [-m MESHES e.g. 1234] [-s SEED] [-w]\n", argv[0]);
            return 2;
        }
    }
    if (mkdir(outdir, 0777) != 0 && errno != EEXIST) die(outdir, strerror(errno));
    rng_state = seed;

    /* particles: eq. 23 */
    const int np = (int)lround(60.0 * 60.0 * 4.0 * ALPHA_MEAN / (PI / 6.0));
    double *xd = malloc(3 * sizeof(double) * (size_t)np);
    double *pos = malloc(3 * sizeof(double) * (size_t)np), *rad = malloc(sizeof(double) * (size_t)np);
    if (!xd || !pos || !rad) die("particles", "out of memory");
    double t0 = program_seconds();
    const long attempts = place_particles(np, xd);
    const double t_place = program_seconds() - t0;
    const double vp = PI / 6.0 * D * D * D;
    const double vsum = np * vp;
    printf("%d particles (d = %g m, region mean alpha_p = %.6f) placed by RSA in %ld attempts, %.2f s\n", np, D,
           np * (PI / 6.0) / (60.0 * 60.0 * 4.0), attempts, t_place);
    printf("expansion kernels %s at walls\n", wall_mirror ? "MIRRORED" : "truncated (not mirrored)");
    FILE *fp = open_out(outdir, "particles.csv");
    fprintf(fp, "# particle centres in units of d = %g m; seed %llu\nx,y,z\n", D, (unsigned long long)seed);
    for (int i = 0; i < np; ++i) {
        fprintf(fp, "%.9f,%.9f,%.9f\n", xd[3 * i], xd[3 * i + 1], xd[3 * i + 2]);
        for (int a = 0; a < 3; ++a) pos[3 * i + a] = xd[3 * i + a] * D;
        rad[i] = 0.5 * D;
    }
    fclose(fp);
    cdc_particles parts = {np, pos, rad, NULL, NULL}; /* no host hints: every build locates from scratch */

    FILE *sum = open_out(outdir, "summary.csv");
    fprintf(sum, "method,dx_over_d,n_expand,mean,std,min,max,conservation_rel_err,seconds,seconds_per_particle\n");
    FILE *hist = NULL;
    const int NBIN = 100; /* histogram bins of width 0.01 on [0, 1) */
    static const uint8_t walls[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL,
                                     CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};
    const double t_all = program_seconds();

    for (const char *mc = mesh_list; *mc; ++mc) {
        const int mj = *mc - '0';
        if (mj < 1 || mj > 4) die("-m", "mesh digits must be 1 to 4");
        const mesh_def md = MESHES[mj - 1];
        const double lo[3] = {-HALF_DOMAIN * D, -HALF_DOMAIN * D, 0.0};
        const double hi[3] = {HALF_DOMAIN * D, HALF_DOMAIN * D, THICKNESS * D};
        const double tm = program_seconds();
        box_mesh b;
        if (box_mesh_create(&b, md.nx, md.ny, md.nz, lo, hi, walls, 0.0) != 0) die("box_mesh_create", "failed");
        cdc_context *ctx = NULL;
        if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) die("cdc_context_create", cdc_create_error());
        /* one-time mesh setup outside the timings: the location bins are built on first need */
        {
            const double p0[3] = {0.0, 0.0, 0.5 * THICKNESS * D};
            int32_t c;
            if (cdc_locate_point(ctx, p0, -1, &c) != CDC_OK || c < 0) die("locate", cdc_last_error(ctx));
        }
        const cdc_mesh *m = &b.mesh;
        const int nc = m->n_cells;
        /* Delta x / d as Table I defines it: V_c^(1/3) / d */
        const double dx_over_d = cbrt(m->cell_volumes[0]) / D;
        printf("\nmesh M%d: %d x %d x %d = %d cells, dx/d = %.4f (setup %.2f s)\n", mj, md.nx, md.ny, md.nz, nc,
               dx_over_d, program_seconds() - tm);

        /* statistics cells and the profile row (centre nearest y = 0; for even ny the row just above) */
        uint8_t *in_stats = malloc((size_t)nc);
        int n_stats = 0;
        for (int c = 0; c < nc; ++c) {
            const double *xc = m->cell_centres + 3 * (size_t)c;
            in_stats[c] = fabs(xc[0]) <= STATS_HALF * D * (1 + 1e-9) && fabs(xc[1]) <= STATS_HALF * D * (1 + 1e-9);
            n_stats += in_stats[c];
        }
        const int jrow = md.ny / 2, kmid = md.nz / 2;
        const double yrow = m->cell_centres[3 * (size_t)box_mesh_cell(&b, 0, jrow, 0) + 1] / D;
        const double zmid = m->cell_centres[3 * (size_t)box_mesh_cell(&b, 0, 0, kmid) + 2] / D;
        double *alpha = malloc(sizeof(double) * (size_t)nc);
        if (!in_stats || !alpha) die("mesh", "out of memory");
        if (mj == 2) {
            hist = open_out(outdir, "histogram_M2.csv");
            fprintf(hist, "# alpha_p histograms at dx/d = 1 (mesh M2) over the %d statistics cells "
                          "(|x|, |y| <= 20 d, all z); density = count / (cells * bin width)\n", n_stats);
            fprintf(hist, "method,n_expand,bin_lo,bin_hi,count,density\n");
        }

        for (int r = 0; r < N_RUNS; ++r) {
            const run_def *run = RUNS + r;
            cdc_kernel_params prm = {0};
            prm.expansion_factor = run->n_expand;
            prm.search_factor = TWO_GRID_SEARCH;
            prm.bandwidth = GAUSS_B * D;
            prm.wall_mirror = wall_mirror;
            cdc_diffusion_params dp = {0};
            dp.bandwidth = DIFFUSION_B * D;

            /* timed: kernel creation and build, alpha_p, diffusion */
            const double ts = program_seconds();
            cdc_kernels *k = NULL;
            if (cdc_kernels_create(ctx, run->core, &prm, &k) != CDC_OK) die(run->name, cdc_last_error(ctx));
            if (cdc_kernels_build(k, &parts) != CDC_OK) die(run->name, cdc_last_error(ctx));
            if (cdc_alpha_p(k, &parts, alpha) != CDC_OK) die(run->name, cdc_last_error(ctx));
            if (run->diffuse && cdc_diffuse(ctx, &dp, alpha) != CDC_OK) die(run->name, cdc_last_error(ctx));
            const double secs = program_seconds() - ts;
            const long entries = cdc_kernels_offsets(k)[np];
            cdc_kernels_destroy(k);

            /* conservation (compensated sum, so the check measures the core, not this loop) and
             * statistics */
            double vtot = 0.0, vcomp = 0.0, s = 0.0, s2 = 0.0, vs = 0.0, amin = INFINITY, amax = -INFINITY;
            for (int c = 0; c < nc; ++c) {
                const double V = m->cell_volumes[c];
                const double term = alpha[c] * V, tsum = vtot + term;
                vcomp += fabs(vtot) >= fabs(term) ? (vtot - tsum) + term : (term - tsum) + vtot; /* Neumaier */
                vtot = tsum;
                if (!in_stats[c]) continue;
                s += alpha[c] * V;
                vs += V;
                if (alpha[c] < amin) amin = alpha[c];
                if (alpha[c] > amax) amax = alpha[c];
            }
            const double mean = s / vs;
            for (int c = 0; c < nc; ++c)
                if (in_stats[c]) s2 += m->cell_volumes[c] * (alpha[c] - mean) * (alpha[c] - mean);
            const double sd = sqrt(s2 / vs);
            vtot += vcomp;
            const double cons = fabs(vtot - vsum) / vsum;
            char nexp[16] = "";
            if (run->n_expand > 0) snprintf(nexp, sizeof nexp, "%d", run->n_expand);
            fprintf(sum, "%s,%.6g,%s,%.10g,%.10g,%.10g,%.10g,%.3e,%.6f,%.4e\n", run->name, dx_over_d, nexp, mean, sd,
                    amin, amax, cons, secs, secs / np);
            fflush(sum);
            char t[64];
            tag(run, t, sizeof t);
            printf("  %-18s mean %.4f std %.4f min %.4f max %.4f  cons %.1e  %8.3f s (%.2e s/particle, %.1f "
                   "cells/kernel)\n",
                   t, mean, sd, amin, amax, cons, secs, secs / np, (double)entries / np);
            fflush(stdout);

            /* profile along y = 0 */
            char name[128];
            snprintf(name, sizeof name, "profile_%s_M%d.csv", t, mj);
            FILE *pf = open_out(outdir, name);
            fprintf(pf, "# %s on M%d (dx/d = %.4f): row of cells j = %d with centre y = %.4f d (nearest y = 0); "
                        "alpha_zavg = mean over all %d z layers, alpha_midz = layer k = %d (centre z = %.4f d)\n",
                    t, mj, dx_over_d, jrow, yrow, md.nz, kmid, zmid);
            fprintf(pf, "x_over_d,alpha_zavg,alpha_midz\n");
            for (int i = 0; i < md.nx; ++i) {
                double za = 0.0;
                for (int kk = 0; kk < md.nz; ++kk) za += alpha[box_mesh_cell(&b, i, jrow, kk)];
                const int32_t cm = box_mesh_cell(&b, i, jrow, kmid);
                fprintf(pf, "%.6f,%.8g,%.8g\n", m->cell_centres[3 * (size_t)cm] / D, za / md.nz, alpha[cm]);
            }
            fclose(pf);

            if (mj == 2) {
                /* histogram (Zhang et al. 2023 Fig. 8) and the mid-z field (Zhang et al. 2023 Fig. 6) */
                long *cnt = calloc((size_t)NBIN, sizeof(long));
                for (int c = 0; c < nc; ++c) {
                    if (!in_stats[c]) continue;
                    int bi = (int)floor(alpha[c] * NBIN);
                    cnt[bi < 0 ? 0 : bi >= NBIN ? NBIN - 1 : bi]++;
                }
                for (int bi = 0; bi < NBIN; ++bi)
                    fprintf(hist, "%s,%s,%.2f,%.2f,%ld,%.6g\n", run->name, nexp, (double)bi / NBIN,
                            (double)(bi + 1) / NBIN, cnt[bi], cnt[bi] / (n_stats * (1.0 / NBIN)));
                free(cnt);
                snprintf(name, sizeof name, "field_%s_M2.csv", t);
                FILE *ff = open_out(outdir, name);
                fprintf(ff, "# %s on M2: alpha_p in layer k = %d (centre z = %.4f d), %d rows (y from %.4f d) x %d "
                            "columns (x from %.4f d), cell size %.4f d\n",
                        t, kmid, zmid, md.ny, m->cell_centres[1] / D, md.nx, m->cell_centres[0] / D, dx_over_d);
                for (int j = 0; j < md.ny; ++j)
                    for (int i = 0; i < md.nx; ++i)
                        /* full precision: tests compare this field with the solver's to round-off */
                        fprintf(ff, "%.17g%c", alpha[box_mesh_cell(&b, i, j, kmid)], i + 1 < md.nx ? ',' : '\n');
                fclose(ff);
            }
        }
        if (hist) {
            fclose(hist);
            hist = NULL;
        }
        free(alpha);
        free(in_stats);
        cdc_context_destroy(ctx);
        box_mesh_destroy(&b);
    }
    fclose(sum);
    printf("\nall meshes and methods: %.2f s (placement %.2f s); results in %s/\n", program_seconds() - t_all, t_place, outdir);
    free(xd);
    free(pos);
    free(rad);
    return 0;
}
