/*
 * stability_core.c -- core-level scenes of the stability suite: every registered
 * void-fraction method (plus the smoothing variants) against
 *
 *   coarse      a liquid-fluidized column, random non-overlapping particles (alpha_p ~ 0.3 in the bed,
 *               some touching the side and bottom walls, some in corners), d/dx = 0.25 ... 5;
 *   dense       a random packing at alpha_p ~ 0.64 and an FCC block (0.7405): the limiter must engage,
 *               count the moved volume and lose nothing;
 *   boundaries  particles touching each wall, along each edge and in each corner of an all-wall box,
 *               also with a 1 % contact overlap into the wall.
 *
 * For each (scene, method, d/dx) it builds the kernels, computes alpha_p, applies the smoothing (if
 * any) and the packing limiter with alphaMax = 1 - alphaMin (alphaMin = 0.3, as the tutorials), and
 * measures:
 *   - kernel sanity: weights >= 0, sum 1 (to 4e-16 x cells in the kernel), cells in range, no particle
 *     outside;
 *   - alpha_f = 1 - alpha_p within [alphaMin, 1] (to 1e-12), no NaN;
 *   - solid volume: |sum_c alpha_p V_c - sum_i V_i| / sum_i V_i before and after the limiter (<= 1e-12);
 *   - momentum: the fluid sources built as the solver builds them (explicit force spread; implicit
 *     Ksl, KslUs from the same kernels, particle force K (gather(U) - v)) balance the particle forces:
 *     |fluid total + particle total| / sum_i |f_i| <= 1e-12;
 *   - limiter bookkeeping: cells counted == cells above alphaMax before limiting, moved volume >= the
 *     excess above alphaMax, moved > 0 iff a cell was over.
 * Prints one "PASS|FAIL: <scene>: <measured>" line per case and ends with "N passed, N failed".
 * Usage: stability_core [--quick]   (quick: fewer particles in the d/dx = 0.25 column)
 */
#include "coarse_dem.h"
#include "tools/box_mesh.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#define PI 3.14159265358979323846
static const double ALPHA_MIN = 0.3;
static int n_pass, n_fail;

static double rnd(unsigned long long *s)
{
    *s ^= *s >> 12;
    *s ^= *s << 25;
    *s ^= *s >> 27;
    return (double)((*s * 2685821657736338717ULL) >> 11) * (1.0 / 9007199254740992.0);
}

/* ------------------------------------------------------------------ method cases */

typedef struct mcase {
    char label[48];
    char method[32];
    cdc_kernel_params prm;
    int smoothing; /* 0 none, 1 diffusion (b = bandwidth_over_d * d), 2 size-aware diffusion */
} mcase;

/* Every registered method with the parameters the tutorials use, plus variants. Parameters that
 * are lengths are set per d/dx by case_params(). Unknown (newly registered) methods are tried with
 * zero parameters, so a method added to the registry is covered (or fails loudly). */
static int make_cases(mcase *c, int with_mirror)
{
    int n = 0;
    for (int m = 0; m < cdc_method_count(); ++m) {
        const char *name = cdc_method_name(m);
        memset(&c[n], 0, sizeof c[n]);
        snprintf(c[n].method, sizeof c[n].method, "%s", name);
        snprintf(c[n].label, sizeof c[n].label, "%s", name);
        ++n;
        if (strcmp(name, "bigParticle") == 0) {
            c[n] = c[n - 1];
            c[n].prm.expansion_factor = 5;
            snprintf(c[n].label, sizeof c[n].label, "bigParticle-n5");
            ++n;
            if (with_mirror) {
                c[n] = c[n - 1];
                c[n].prm.wall_mirror = 1;
                snprintf(c[n].label, sizeof c[n].label, "bigParticle-n5-mirror");
                ++n;
            }
        }
        if (with_mirror && (strcmp(name, "twoGrid") == 0 || strcmp(name, "gaussian") == 0)) {
            c[n] = c[n - 1];
            c[n].prm.wall_mirror = 1;
            snprintf(c[n].label, sizeof c[n].label, "%s-mirror", name);
            ++n;
        }
        if (strcmp(name, "centre") == 0) {
            c[n] = c[n - 1];
            c[n].smoothing = 1;
            snprintf(c[n].label, sizeof c[n].label, "centre+diffusion");
            ++n;
            c[n] = c[n - 2];
            c[n].smoothing = 2;
            snprintf(c[n].label, sizeof c[n].label, "centre+sizeAwareDiffusion");
            ++n;
        }
    }
    return n;
}

/* length parameters: gaussian b = max(1.5 dx, d) (cutoff 2 b); diffusion b = max(2 dx, 2 d) */
static void case_params(const mcase *mc, double d, double dx, cdc_kernel_params *prm, double *diff_b)
{
    *prm = mc->prm;
    if (strcmp(mc->method, "gaussian") == 0) prm->bandwidth = fmax(1.5 * dx, d);
    *diff_b = fmax(2 * dx, 2 * d);
}

/* ------------------------------------------------------------------ particle sets */

typedef struct pset {
    int n, cap;
    double *x, *r;
    double *v;       /* particle velocity */
    double *K, *fo;  /* drag coefficient, other (explicit) force */
} pset;

static void pset_init(pset *p, int cap)
{
    memset(p, 0, sizeof *p);
    p->cap = cap;
    p->x = malloc(3 * (size_t)cap * sizeof(double));
    p->r = malloc((size_t)cap * sizeof(double));
    p->v = malloc(3 * (size_t)cap * sizeof(double));
    p->K = malloc((size_t)cap * sizeof(double));
    p->fo = malloc(3 * (size_t)cap * sizeof(double));
}

static void pset_free(pset *p)
{
    free(p->x); free(p->r); free(p->v); free(p->K); free(p->fo);
}

static void pset_add(pset *p, const double x[3], double r)
{
    if (p->n >= p->cap) return;
    memcpy(p->x + 3 * p->n, x, 3 * sizeof(double));
    p->r[p->n++] = r;
}

/* uniform hash grid for overlap queries (monodisperse, bin = d) */
typedef struct grid {
    double lo[3], h;
    int n[3];
    int *head, *next;
} grid;

static void grid_init(grid *g, const double lo[3], const double hi[3], double h, int cap)
{
    g->h = h;
    for (int k = 0; k < 3; ++k) {
        g->lo[k] = lo[k];
        g->n[k] = (int)ceil((hi[k] - lo[k]) / h) + 1;
    }
    const size_t nb = (size_t)g->n[0] * g->n[1] * g->n[2];
    g->head = malloc(nb * sizeof(int));
    for (size_t i = 0; i < nb; ++i) g->head[i] = -1;
    g->next = malloc((size_t)cap * sizeof(int));
}

static void grid_free(grid *g) { free(g->head); free(g->next); }

static void grid_ijk(const grid *g, const double *x, int ijk[3])
{
    for (int k = 0; k < 3; ++k) {
        int i = (int)floor((x[k] - g->lo[k]) / g->h);
        ijk[k] = i < 0 ? 0 : (i >= g->n[k] ? g->n[k] - 1 : i);
    }
}

static void grid_insert(grid *g, const double *x, int id)
{
    int b[3];
    grid_ijk(g, x, b);
    const size_t q = ((size_t)b[2] * g->n[1] + b[1]) * g->n[0] + b[0];
    g->next[id] = g->head[q];
    g->head[q] = id;
}

/* 1 if a sphere at x with radius r overlaps any particle in the grid (all radii <= g->h / 2) */
static int grid_overlaps(const grid *g, const pset *p, const double *x, double r)
{
    int b[3];
    grid_ijk(g, x, b);
    for (int k = b[2] - 1; k <= b[2] + 1; ++k)
        for (int j = b[1] - 1; j <= b[1] + 1; ++j)
            for (int i = b[0] - 1; i <= b[0] + 1; ++i) {
                if (i < 0 || j < 0 || k < 0 || i >= g->n[0] || j >= g->n[1] || k >= g->n[2]) continue;
                for (int q = g->head[((size_t)k * g->n[1] + j) * g->n[0] + i]; q >= 0; q = g->next[q]) {
                    const double dx = x[0] - p->x[3 * q], dy = x[1] - p->x[3 * q + 1], dz = x[2] - p->x[3 * q + 2];
                    const double s = r + p->r[q];
                    if (dx * dx + dy * dy + dz * dz < s * s * (1 - 1e-12)) return 1;
                }
            }
    return 0;
}

/* Random sequential addition of non-overlapping spheres of radius r in [lo, hi] up to solid
 * fraction target (or cap particles): a liquid-fluidized bed. A fifth of the attempts are placed
 * touching a random wall (x, y sides or the bottom), and the four bottom corners are filled first. */
static void fill_bed(pset *p, const double lo[3], const double hi[3], double r, double target, int cap,
                     unsigned long long *s)
{
    grid g;
    grid_init(&g, lo, hi, 2 * r, cap);
    const double vp = 4.0 / 3.0 * PI * r * r * r;
    const double vreg = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
    const int want = (int)fmin(cap, target * vreg / vp);
    for (int c = 0; c < 4; ++c) { /* bottom corners: touching three walls */
        const double x[3] = {c & 1 ? hi[0] - r : lo[0] + r, c & 2 ? hi[1] - r : lo[1] + r, lo[2] + r};
        if (!grid_overlaps(&g, p, x, r)) { grid_insert(&g, x, p->n); pset_add(p, x, r); }
    }
    long tries = 0;
    const long max_tries = 300L * want + 10000;
    while (p->n < want && tries++ < max_tries) {
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + r + (hi[k] - lo[k] - 2 * r) * rnd(s);
        if (rnd(s) < 0.2) { /* touching a wall */
            const int w = (int)(5 * rnd(s));
            if (w == 0) x[0] = lo[0] + r;
            else if (w == 1) x[0] = hi[0] - r;
            else if (w == 2) x[1] = lo[1] + r;
            else if (w == 3) x[1] = hi[1] - r;
            else x[2] = lo[2] + r;
        }
        if (grid_overlaps(&g, p, x, r)) continue;
        grid_insert(&g, x, p->n);
        pset_add(p, x, r);
    }
    grid_free(&g);
}

/* Random dense packing of n spheres of radius r in [lo, hi]: random positions, then overlap removal
 * (each overlapping pair moved apart by its overlap, shared; positions clamped to the box) until the
 * largest overlap is below tol * d or max_iter sweeps. Returns the largest remaining overlap / d. */
static double pack_dense(pset *p, const double lo[3], const double hi[3], double r, int n, int max_iter,
                         double tol, unsigned long long *s, double *mean_overlap)
{
    const int first = p->n;
    for (int i = 0; i < n; ++i) {
        double x[3];
        for (int k = 0; k < 3; ++k) x[k] = lo[k] + r + (hi[k] - lo[k] - 2 * r) * rnd(s);
        pset_add(p, x, r);
    }
    double *dsp = malloc(3 * (size_t)n * sizeof(double));
    int *cnt = malloc((size_t)n * sizeof(int));
    double worst = 0;
    for (int it = 0; it < max_iter; ++it) {
        grid g;
        grid_init(&g, lo, hi, 2 * r, p->n);
        for (int i = 0; i < n; ++i) grid_insert(&g, p->x + 3 * (first + i), i);
        memset(dsp, 0, 3 * (size_t)n * sizeof(double));
        memset(cnt, 0, (size_t)n * sizeof(int));
        worst = 0;
        double osum = 0;
        int npairs = 0;
        for (int i = 0; i < n; ++i) {
            const double *xi = p->x + 3 * (first + i);
            int b[3];
            grid_ijk(&g, xi, b);
            for (int k = b[2] - 1; k <= b[2] + 1; ++k)
                for (int j = b[1] - 1; j <= b[1] + 1; ++j)
                    for (int ii = b[0] - 1; ii <= b[0] + 1; ++ii) {
                        if (ii < 0 || j < 0 || k < 0 || ii >= g.n[0] || j >= g.n[1] || k >= g.n[2]) continue;
                        for (int q = g.head[((size_t)k * g.n[1] + j) * g.n[0] + ii]; q >= 0; q = g.next[q]) {
                            if (q <= i) continue;
                            const double *xq = p->x + 3 * (first + q);
                            double dv[3] = {xq[0] - xi[0], xq[1] - xi[1], xq[2] - xi[2]};
                            double dist = sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]);
                            const double ov = 2 * r - dist;
                            if (ov <= 0) continue;
                            worst = fmax(worst, ov);
                            osum += ov;
                            ++npairs;
                            if (dist < 1e-12 * r) { dv[0] = rnd(s) - 0.5; dv[1] = rnd(s) - 0.5; dv[2] = rnd(s) - 0.5;
                                dist = sqrt(dv[0] * dv[0] + dv[1] * dv[1] + dv[2] * dv[2]); }
                            for (int a = 0; a < 3; ++a) {
                                const double m = 0.5 * 1.05 * ov * dv[a] / dist;
                                dsp[3 * q + a] += m;
                                dsp[3 * i + a] -= m;
                            }
                            ++cnt[i]; ++cnt[q];
                        }
                    }
        }
        grid_free(&g);
        *mean_overlap = npairs ? osum / npairs / (2 * r) : 0;
        if (worst < tol * 2 * r) break;
        for (int i = 0; i < n; ++i) {
            if (!cnt[i]) continue;
            double *xi = p->x + 3 * (first + i);
            for (int a = 0; a < 3; ++a) {
                xi[a] += dsp[3 * i + a] / sqrt((double)cnt[i]);
                xi[a] = fmin(fmax(xi[a], lo[a] + r), hi[a] - r);
            }
        }
    }
    free(dsp);
    free(cnt);
    return worst / (2 * r);
}

/* per-particle velocities and forces for the momentum balance: drag coefficient K_i > 0 (Stokes-like
 * scale, randomised), velocity v_i, an explicit force (pressure-gradient-like) */
static void set_dynamics(pset *p, unsigned long long *s)
{
    for (int i = 0; i < p->n; ++i) {
        p->K[i] = 3 * PI * 1e-3 * 2 * p->r[i] * (1 + 5 * rnd(s));
        for (int a = 0; a < 3; ++a) {
            p->v[3 * i + a] = 0.1 * (rnd(s) - 0.5) + (a == 2 ? 0.02 : 0);
            p->fo[3 * i + a] = 1e3 * 9.81 * 4.0 / 3.0 * PI * pow(p->r[i], 3) * (rnd(s) - 0.3);
        }
    }
}

/* ------------------------------------------------------------------ the measurement */

typedef struct result {
    int ok_build, outside;
    double w_sum_err, w_min;
    int bad_cell;
    double vol_rel_pre, vol_rel_post;
    double af_min, af_max;
    int nan;
    double mom_explicit, mom_implicit;
    double moved, excess;
    int n_limited, n_over;
    int limiter_ok;
    int have_alpha;
    char err[320];
} result;

static double sum_volume(const pset *p)
{
    double v = 0;
    for (int i = 0; i < p->n; ++i) v += 4.0 / 3.0 * PI * p->r[i] * p->r[i] * p->r[i];
    return v;
}

static int measure(cdc_context *ctx, const mcase *mc, pset *ps, double d, double dx, unsigned long long *s,
                   result *res)
{
    memset(res, 0, sizeof *res);
    const cdc_mesh *m = cdc_context_mesh(ctx);
    const size_t nc = (size_t)m->n_cells;
    cdc_kernel_params prm;
    double diff_b;
    case_params(mc, d, dx, &prm, &diff_b);
    cdc_kernels *k = NULL;
    cdc_status st = cdc_kernels_create(ctx, mc->method, &prm, &k);
    if (st != CDC_OK) {
        snprintf(res->err, sizeof res->err, "create: %s", cdc_last_error(ctx));
        return 0;
    }
    cdc_particles cp = {ps->n, ps->x, ps->r, NULL, NULL};
    st = cdc_kernels_build(k, &cp);
    res->outside = cdc_kernels_outside(k, NULL);
    if (st != CDC_OK) {
        snprintf(res->err, sizeof res->err, "build: %s", cdc_last_error(ctx));
        cdc_kernels_destroy(k);
        return 0;
    }
    res->ok_build = 1;
    const int32_t *off = cdc_kernels_offsets(k), *cells = cdc_kernels_cells(k);
    const double *w = cdc_kernels_weights(k);
    res->w_min = 1;
    for (int i = 0; i < ps->n; ++i) {
        double sum = 0;
        for (int e = off[i]; e < off[i + 1]; ++e) {
            sum += w[e];
            res->w_min = fmin(res->w_min, w[e]);
            if (cells[e] < 0 || cells[e] >= m->n_cells) res->bad_cell = 1;
        }
        /* normalising n weights leaves a round-off of order n eps in their sum (as tests/core):
         * measured relative to 4e-16 n, so <= 1 passes */
        const int ne = off[i + 1] - off[i];
        res->w_sum_err = fmax(res->w_sum_err, fabs(sum - 1) / (4e-16 * (ne > 1 ? ne : 1)));
    }

    double *a = malloc(nc * sizeof(double));
    double *pre = malloc(nc * sizeof(double));
    if (mc->smoothing == 2) {
        cdc_diffusion_params base = {0};
        base.n_steps = 4;
        int ncls = 0;
        st = cdc_alpha_p_diffused_by_size(ctx, k, &cp, diff_b / d, 1.1, &base, a, &ncls);
    } else {
        st = cdc_alpha_p(k, &cp, a);
        if (st == CDC_OK && mc->smoothing == 1) {
            cdc_diffusion_params dp = {0};
            dp.bandwidth = diff_b;
            dp.n_steps = 4;
            st = cdc_diffuse(ctx, &dp, a);
        }
    }
    const double vp = sum_volume(ps);
    const double amax = 1 - ALPHA_MIN;
    if (st == CDC_OK) {
        double vs = 0;
        for (size_t c = 0; c < nc; ++c) {
            vs += a[c] * m->cell_volumes[c];
            if (a[c] > amax) {
                ++res->n_over;
                res->excess += (a[c] - amax) * m->cell_volumes[c];
            }
        }
        res->vol_rel_pre = fabs(vs - vp) / vp;
        memcpy(pre, a, nc * sizeof(double));
        double moved = 0;
        int32_t nlim = 0;
        st = cdc_limit_packing(ctx, amax, 200, a, &moved, &nlim);
        res->moved = moved;
        res->n_limited = nlim;
    }
    if (st == CDC_ERR_NOT_CONVERGED) {
        /* the solver's 200 sweeps were not enough: how many would be (powers of 2 up to 102400)? */
        char msg[160];
        snprintf(msg, sizeof msg, "%s", cdc_last_error(ctx));
        int need = 0;
        for (int sweeps = 400; sweeps <= 102400 && !need; sweeps *= 2) {
            memcpy(a, pre, nc * sizeof(double));
            if (cdc_limit_packing(ctx, amax, sweeps, a, NULL, NULL) == CDC_OK) need = sweeps;
        }
        if (need)
            snprintf(res->err, sizeof res->err, "%s (solver's max_sweeps 200; converges within %d sweeps)", msg, need);
        else
            snprintf(res->err, sizeof res->err, "%s (not converged within 102400 sweeps either)", msg);
        free(a); free(pre);
        cdc_kernels_destroy(k);
        return 0;
    }
    if (st != CDC_OK) {
        snprintf(res->err, sizeof res->err, "alpha/limiter: %s", cdc_last_error(ctx));
        free(a); free(pre);
        cdc_kernels_destroy(k);
        return 0;
    }
    double vs = 0;
    res->af_min = 1e300;
    res->af_max = -1e300;
    for (size_t c = 0; c < nc; ++c) {
        if (!isfinite(a[c])) ++res->nan;
        vs += a[c] * m->cell_volumes[c];
        res->af_min = fmin(res->af_min, 1 - a[c]);
        res->af_max = fmax(res->af_max, 1 - a[c]);
    }
    res->vol_rel_post = fabs(vs - vp) / vp;
    res->have_alpha = 1;
    /* the limiter counted what was over and moved at least the excess */
    res->limiter_ok = res->n_limited == res->n_over && res->moved >= res->excess * (1 - 1e-12) &&
                      ((res->n_over > 0) == (res->moved > 0));

    /* momentum, as coarseDemCoupling builds it (cdc_exchange_sources): the particle gets
     * K (gather(U) - v) + f_o; the fluid -Ksl U + KslUs + f_fluid, explicit and implicit */
    set_dynamics(ps, s);
    double *U = malloc(3 * nc * sizeof(double)), *u = malloc(3 * (size_t)ps->n * sizeof(double));
    double *F = malloc(3 * nc * sizeof(double)), *Ksl = malloc(nc * sizeof(double));
    double *KUs = malloc(3 * nc * sizeof(double));
    for (size_t c = 0; c < 3 * nc; ++c) U[c] = 0.1 * (rnd(s) - 0.5) + (c % 3 == 2 ? 0.05 : 0);
    int ok = cdc_gather(k, U, 3, u) == CDC_OK;
    double fp[3] = {0, 0, 0}, scale = 0;
    for (int i = 0; i < ps->n; ++i)
        for (int c3 = 0; c3 < 3; ++c3) {
            const double f = ps->K[i] * (u[3 * i + c3] - ps->v[3 * i + c3]) + ps->fo[3 * i + c3];
            fp[c3] += f;
            scale += fabs(f);
        }
    const double rho = 1.0;
    for (int mode = 0; mode < 2 && ok; ++mode) {
        const cdc_exchange_in in = {ps->n, ps->K, ps->v, u, NULL, ps->fo, rho,
                                    mode ? CDC_EXCHANGE_EXPLICIT : CDC_EXCHANGE_IMPLICIT};
        ok = cdc_exchange_sources(k, &in, Ksl, KUs, F) == CDC_OK;
        double fe[3] = {0, 0, 0};
        for (size_t c = 0; c < nc; ++c)
            for (int c3 = 0; c3 < 3; ++c3)
                fe[c3] += rho * (-Ksl[c] * U[3 * c + c3] + KUs[3 * c + c3] + F[3 * c + c3]) * m->cell_volumes[c];
        double worst = 0;
        for (int c3 = 0; c3 < 3; ++c3) worst = fmax(worst, fabs(fe[c3] + fp[c3]) / scale);
        if (mode) res->mom_explicit = worst; else res->mom_implicit = worst;
    }
    if (!ok) snprintf(res->err, sizeof res->err, "exchange: %s", cdc_last_error(ctx));

    free(U); free(u); free(F); free(Ksl); free(KUs);
    free(a); free(pre);
    cdc_kernels_destroy(k);
    return ok;
}

/* The common pass criteria; extra (scene-specific) conditions are and-ed in by the caller. */
static int passes(const result *r, int ok)
{
    return ok && r->ok_build && r->outside == 0 && !r->bad_cell && r->w_min >= 0 && r->w_sum_err <= 1 &&
           r->nan == 0 && r->vol_rel_pre <= 1e-12 && r->vol_rel_post <= 1e-12 &&
           r->af_min >= ALPHA_MIN - 1e-12 && r->af_max <= 1 + 1e-15 && r->mom_explicit <= 1e-12 &&
           r->mom_implicit <= 1e-12 && r->limiter_ok;
}

static void report(const char *scene, int pass, const result *r, const char *extra)
{
    if (pass) ++n_pass; else ++n_fail;
    if (!r->have_alpha) {
        printf("%s: %s: limiter over %d cells (excess %.3e m3) stopped with ERROR %s%s%s\n", pass ? "PASS" : "FAIL",
               scene, r->n_over, r->excess, r->err, extra ? extra : "", r->outside ? " particles outside!" : "");
        fflush(stdout);
        return;
    }
    printf("%s: %s: alpha_f [%.6f, %.6f] nan %d, solid volume rel.err %.1e/%.1e (pre/post limiter), "
           "momentum rel.err %.1e/%.1e (explicit/implicit), limiter %d cells moved %.3e m3 (excess %.3e)%s%s%s%s\n",
           pass ? "PASS" : "FAIL", scene, r->af_min, r->af_max, r->nan, r->vol_rel_pre, r->vol_rel_post,
           r->mom_explicit, r->mom_implicit, r->n_limited, r->moved, r->excess, extra ? extra : "",
           r->err[0] ? " ERROR " : "", r->err, r->outside ? " particles outside!" : "");
    if (!pass && r->ok_build && (r->w_min < 0 || r->w_sum_err > 1 || r->bad_cell))
        printf("    kernel weights: min %.3e, |sum-1| max %.3g x 4e-16 n_cells, bad cell index %d\n", r->w_min, r->w_sum_err,
               r->bad_cell);
    if (!pass && !r->limiter_ok)
        printf("    limiter bookkeeping: counted %d cells, %d were above alphaMax\n", r->n_limited, r->n_over);
    fflush(stdout);
}

/* ------------------------------------------------------------------ scenes */

static const uint8_t COLUMN_KINDS[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL,
                                        CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_OTHER};
static const uint8_t ALL_WALLS[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL,
                                     CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};

/* Scene 1: liquid-fluidized column, d/dx = ratio. Width max(10 dx, 4 d), height 4 widths, a bed of
 * non-overlapping particles at alpha_p 0.3 over the lower half (capped at cap particles: then the bed
 * is lower). Walls on the sides and the bottom, an outlet on top. */
static void scene_coarse(double ratio, int cap, const mcase *cases, int nc_cases)
{
    const double dx = 1e-3, d = ratio * dx;
    const int w = (int)fmax(10, ceil(4 * ratio));
    box_mesh b;
    const double lo[3] = {0, 0, 0}, hi[3] = {w * dx, w * dx, 4 * w * dx};
    if (box_mesh_create(&b, w, w, 4 * w, lo, hi, COLUMN_KINDS, 0.0)) { printf("FAIL: coarse: mesh\n"); ++n_fail; return; }
    cdc_context *ctx = NULL;
    if (cdc_context_create(&b.mesh, &ctx) != CDC_OK) {
        printf("FAIL: coarse: context %s\n", cdc_create_error()); ++n_fail; box_mesh_destroy(&b); return;
    }
    unsigned long long s = 1000 + (unsigned long long)(100 * ratio);
    pset ps;
    pset_init(&ps, cap);
    /* the bed: the lower half, or lower when capped (fine particles), always at alpha_p 0.3 */
    const double vp1 = PI / 6 * d * d * d;
    const double bed_h = fmin(2 * w * dx, fmax(2 * d, cap * vp1 / (0.30 * hi[0] * hi[1])));
    const double bed_hi[3] = {hi[0], hi[1], bed_h};
    fill_bed(&ps, lo, bed_hi, d / 2, 0.30, cap, &s);
    /* bed alpha over the height the particles occupy */
    double zmax = 0;
    int touching = 0;
    for (int i = 0; i < ps.n; ++i) {
        zmax = fmax(zmax, ps.x[3 * i + 2] + ps.r[i]);
        const double *x = ps.x + 3 * i, r = ps.r[i];
        if (x[0] - r < 1e-12 * dx || x[0] + r > hi[0] - 1e-12 * dx || x[1] - r < 1e-12 * dx ||
            x[1] + r > hi[1] - 1e-12 * dx || x[2] - r < 1e-12 * dx)
            ++touching;
    }
    const double bed_alpha = sum_volume(&ps) / (hi[0] * hi[1] * zmax);
    for (int m = 0; m < nc_cases; ++m) {
        result r;
        clock_t t0 = clock();
        const int ok = measure(ctx, &cases[m], &ps, d, dx, &s, &r);
        char scene[160], extra[192];
        snprintf(scene, sizeof scene, "coarse/%s/d_dx=%g", cases[m].label, ratio);
        snprintf(extra, sizeof extra, "; %d particles (%d touching walls), bed alpha_p %.3f, %dx%dx%d cells, %.2f s",
                 ps.n, touching, bed_alpha, w, w, 4 * w, (double)(clock() - t0) / CLOCKS_PER_SEC);
        report(scene, passes(&r, ok), &r, extra);
    }
    pset_free(&ps);
    cdc_context_destroy(ctx);
    box_mesh_destroy(&b);
}

/* Scene 2: dense packings in a 14 x 14 x 20 d box (all walls): a random packing at alpha_p ~ 0.64 or
 * an FCC block (0.7405) filling the lower part. The limiter must engage for the FCC block with every
 * method (the block's mean solid fraction is above alphaMax = 0.7); for the random packing it engages
 * where the kernel is narrow enough. */
static void scene_dense(int fcc, double ratio, const mcase *cases, int nc_cases, int quick)
{
    const double dx = 1e-3, d = ratio * dx;
    const double L = (fcc ? 10 : quick ? 6 : 8) * d; /* packed region edge */
    const int nxy = (int)ceil(L / dx + 2 * ratio); /* mesh: region plus d on each side */
    const double H = nxy * dx;
    const int nz = (int)ceil(2 * L / dx);
    box_mesh b;
    const double lo[3] = {0, 0, 0}, hi[3] = {H, H, nz * dx};
    box_mesh_create(&b, nxy, nxy, nz, lo, hi, ALL_WALLS, 0.0);
    cdc_context *ctx = NULL;
    cdc_context_create(&b.mesh, &ctx);
    unsigned long long s = fcc ? 77 : 64;
    pset ps;
    const double r = d / 2;
    /* region: centred in x, y; sitting on the bottom wall */
    const double rlo[3] = {(H - L) / 2, (H - L) / 2, 0}, rhi[3] = {(H + L) / 2, (H + L) / 2, L};
    double overlap = 0, mean_overlap = 0, alpha_region;
    if (fcc) {
        const double a = d * sqrt(2.0); /* cube edge of the FCC unit cell: touching along face diagonals */
        const int nu = (int)floor((L - d) / a) + 1;
        pset_init(&ps, 4 * (nu + 1) * (nu + 1) * (nu + 1));
        static const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
        for (int k = 0; k < nu; ++k)
            for (int j = 0; j < nu; ++j)
                for (int i = 0; i < nu; ++i)
                    for (int q = 0; q < 4; ++q) {
                        const double x[3] = {rlo[0] + r + a * (i + basis[q][0]), rlo[1] + r + a * (j + basis[q][1]),
                                             rlo[2] + r + a * (k + basis[q][2])};
                        pset_add(&ps, x, r);
                    }
        /* solid fraction of the lattice's own volume (nu^3 unit cells hold 4 nu^3 spheres) */
        alpha_region = 4 * nu * nu * nu * PI / 6 * d * d * d / pow(nu * a, 3);
    } else {
        const double vreg = L * L * L;
        const int n = (int)lround(0.64 * vreg / (PI / 6 * d * d * d));
        pset_init(&ps, n);
        overlap = pack_dense(&ps, rlo, rhi, r, n, quick ? 1500 : 4000, 2e-3, &s, &mean_overlap);
        alpha_region = sum_volume(&ps) / vreg;
    }
    for (int m = 0; m < nc_cases; ++m) {
        result res;
        const int ok = measure(ctx, &cases[m], &ps, d, dx, &s, &res);
        char scene[160], extra[256];
        snprintf(scene, sizeof scene, "dense/%s/%s/d_dx=%g", fcc ? "fcc074" : "random064", cases[m].label, ratio);
        /* FCC: the limiter must have engaged (the block is above alphaMax on average) */
        const int engaged = res.n_limited > 0 && res.moved > 0;
        int pass = passes(&res, ok) && (!fcc || engaged);
        if (fcc)
            snprintf(extra, sizeof extra, "; %d particles, lattice alpha_p %.4f, limiter engaged: %s", ps.n,
                     alpha_region, engaged ? "yes" : "NO");
        else
            snprintf(extra, sizeof extra, "; %d particles, region alpha_p %.4f (residual overlap max %.1f %%, mean %.2f %% of d), "
                     "limiter engaged: %s", ps.n, alpha_region, 100 * overlap, 100 * mean_overlap, engaged ? "yes" : "no");
        report(scene, pass, &res, extra);
    }
    pset_free(&ps);
    cdc_context_destroy(ctx);
    box_mesh_destroy(&b);
}

/* Scene 3 (core part): an all-wall box of 12 x 12 x 12 cells (at least 5 d wide); particles touching
 * each of the 6 walls (centre r from it), along each of the 12 edges, in each of the 8 corners, and
 * the same set again pushed 1 % of d into the walls (DEM contact overlap: part of the sphere is
 * outside the mesh; the kernel must still carry the whole volume). */
static void scene_boundaries(double ratio, const mcase *cases, int nc_cases)
{
    const double dx = 1e-3, d = ratio * dx, r = d / 2;
    const int n = (int)fmax(12, ceil(5 * ratio));
    const double H = n * dx;
    box_mesh b;
    const double lo[3] = {0, 0, 0}, hi[3] = {H, H, H};
    box_mesh_create(&b, n, n, n, lo, hi, ALL_WALLS, 0.0);
    cdc_context *ctx = NULL;
    cdc_context_create(&b.mesh, &ctx);
    unsigned long long s = 31 + (unsigned long long)(10 * ratio);
    pset ps;
    pset_init(&ps, 2 * (6 + 12 + 8));
    for (int pass = 0; pass < 2; ++pass) {
        const double gap = pass == 0 ? r : r - 0.01 * d; /* touching, then 1 % overlap into the wall */
        const double mid = H / 2;
        for (int f = 0; f < 6; ++f) { /* faces: off-centre positions along the face */
            double x[3] = {mid + 0.13 * H * (rnd(&s) - 0.5), mid + 0.13 * H * (rnd(&s) - 0.5),
                           mid + 0.13 * H * (rnd(&s) - 0.5)};
            x[f / 2] = f % 2 ? H - gap : gap;
            pset_add(&ps, x, r);
        }
        for (int e = 0; e < 12; ++e) { /* edges: axis e / 4 free, the other two at walls */
            const int ax = e / 4, a1 = (ax + 1) % 3, a2 = (ax + 2) % 3;
            double x[3];
            x[ax] = 0.3 * H + 0.4 * H * rnd(&s) + (pass ? 0.05 * H : 0);
            x[a1] = e & 1 ? H - gap : gap;
            x[a2] = e & 2 ? H - gap : gap;
            pset_add(&ps, x, r);
        }
        for (int c = 0; c < 8; ++c) {
            const double x[3] = {c & 1 ? H - gap : gap, c & 2 ? H - gap : gap, c & 4 ? H - gap : gap};
            pset_add(&ps, x, r);
        }
    }
    /* the 1 % overlap copies sit on top of the touching ones in the corners: fine for the kernels */
    for (int m = 0; m < nc_cases; ++m) {
        result res;
        const int ok = measure(ctx, &cases[m], &ps, d, dx, &s, &res);
        char scene[160], extra[128];
        snprintf(scene, sizeof scene, "boundaries/%s/d_dx=%g", cases[m].label, ratio);
        snprintf(extra, sizeof extra, "; %d particles on faces, edges, corners (touching and 1 %% into the walls)",
                 ps.n);
        report(scene, passes(&res, ok), &res, extra);
    }
    pset_free(&ps);
    cdc_context_destroy(ctx);
    box_mesh_destroy(&b);
}

int main(int argc, char **argv)
{
    int quick = 0;
    const char *only = NULL;
    for (int i = 1; i < argc; ++i) {
        if (strcmp(argv[i], "--quick") == 0) quick = 1;
        else if (strcmp(argv[i], "--full") == 0) quick = 0;
        else only = argv[i]; /* coarse | dense | boundaries */
    }
    mcase cases[32], cases_m[32];
    const int nc = make_cases(cases, 0), ncm = make_cases(cases_m, 1);
    if (!only || strcmp(only, "coarse") == 0) {
        const double ratios[] = {0.25, 0.5, 1, 2, 3, 5};
        for (int i = 0; i < 6; ++i) scene_coarse(ratios[i], quick ? 6000 : 20000, cases, nc);
    }
    if (!only || strcmp(only, "dense") == 0) {
        scene_dense(0, 1, cases, nc, quick);
        scene_dense(1, 1, cases, nc, quick);
        if (!quick) {
            scene_dense(0, 2, cases, nc, quick);
            scene_dense(1, 2, cases, nc, quick);
        }
    }
    if (!only || strcmp(only, "boundaries") == 0) {
        const double ratios[] = {0.5, 1, 3};
        for (int i = 0; i < 3; ++i) scene_boundaries(ratios[i], cases_m, ncm);
    }
    printf("%d passed, %d failed\n", n_pass, n_fail);
    return n_fail ? 1 : 0;
}
