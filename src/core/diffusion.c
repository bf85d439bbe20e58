/*
 * diffusion.c -- diffusion-based smoothing (Sun & Xiao; Zhang et al., Phys. Fluids 35, 113330
 * (2023), §II.C, eq. 7).
 *
 * Formulation: d(phi)/dtau = div(D grad phi) in pseudo-time tau, zero flux through every boundary
 * face (walls, inlets, outlets alike, as the paper requires for conservation), integrated to
 * T = b^2/4 so that, with D = 1, a point source spreads like the Gaussian kernel exp(-r^2/b^2).
 * Finite volumes, two-point flux a_f (phi_N - phi_P) with a_f = D_f |S_f| / |C_N - C_P| (no
 * non-orthogonal correction: exact on orthogonal meshes, conservative on any mesh). Implicit Euler
 * in n_steps equal steps, each solved by conjugate gradients preconditioned with the incomplete
 * Cholesky factorisation without fill-in (DIC, Meijerink & van der Vorst 1977; OpenFOAM's DIC) when
 * the internal faces come in upper-triangular order (owner < neighbour, owners ascending: every
 * OpenFOAM mesh), else with the diagonal (Jacobi). The matrix does not change between couplings on a
 * fixed mesh; at b = 6 cells DIC needs about half of Jacobi's iterations.
 *
 * Conservation to round-off whatever the solver tolerance: the step's final value is written in
 * flux form, phi_new = phi_old + dtau/V * sum_f a_f (phi*_N - phi*_P), where phi* is the CG
 * solution. Each face flux leaves one cell and enters the other, so sum(phi V) cannot change.
 *
 * Parallel: the core sees one rank's mesh. Without a halo (cdc_context_set_halo) processor faces
 * are zero-flux; with one, each processor face carries the same two-point flux with the neighbour
 * rank's value from the caller's exchange, and the CG's dot products are summed over the ranks, so
 * the ranks solve the serial system together (the preconditioner is each rank's own, without the
 * processor faces, as in OpenFOAM: it changes the iterates, not the system solved). Both sides of a processor face compute the same flux
 * from the same exchanged values (given the same coefficient on both sides, which the caller
 * ensures), so the flux-form update conserves the total over all ranks. The global sums must give
 * every rank the same bits: the CG's stopping test, and so the number of collective exchanges,
 * depends on them.
 */
#include "internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static cdc_status face_coefficients(cdc_context *ctx)
{
    if (ctx->face_coeff) return CDC_OK;
    const cdc_mesh *m = ctx->mesh;
    ctx->face_coeff = malloc((size_t)(m->n_internal_faces > 0 ? m->n_internal_faces : 1) * sizeof(double));
    if (!ctx->face_coeff) return cdc_fail(ctx, CDC_ERR_NOMEM, "diffusion: out of memory");
    for (int32_t f = 0; f < m->n_internal_faces; ++f) {
        const double *S = m->face_areas + 3 * (size_t)f;
        const double d = sqrt(cdc_dist2(m->cell_centres + 3 * (size_t)m->owner[f],
                                        m->cell_centres + 3 * (size_t)m->neighbour[f]));
        ctx->face_coeff[f] = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]) / d;
    }
    return CDC_OK;
}

/* y = K x, the (negative semi-definite) Laplacian times volume: y_P = sum_f a_f (x_N - x_P), over
 * internal faces and, with a halo, processor faces (coefficients ctx->halo_coeff). */
static cdc_status laplacian(cdc_context *ctx, const double *a, const double *x, double *y)
{
    const cdc_mesh *m = ctx->mesh;
    memset(y, 0, (size_t)m->n_cells * sizeof *y);
    for (int32_t f = 0; f < m->n_internal_faces; ++f) {
        const int32_t o = m->owner[f], n = m->neighbour[f];
        const double flux = a[f] * (x[n] - x[o]);
        y[o] += flux;
        y[n] -= flux;
    }
    if (!ctx->has_halo) return CDC_OK;
    const cdc_halo *h = &ctx->halo;
    double *xn = ctx->halo_nbr.v;
    if (h->exchange(h->user, x, xn))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the halo exchange failed");
    for (int32_t i = 0; i < h->n_faces; ++i) y[h->cell[i]] += ctx->halo_coeff.v[i] * (xn[i] - x[h->cell[i]]);
    return CDC_OK;
}

/* values[0..n) summed over the ranks (nothing to do in serial) */
static cdc_status global_sum(cdc_context *ctx, double *values, int n)
{
    if (ctx->has_halo && ctx->halo.sum(ctx->halo.user, values, n))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the global sum failed");
    return CDC_OK;
}

/* Can the faces carry DIC's sweeps (owner < neighbour, owners ascending)? */
static int upper_triangular(const cdc_mesh *m)
{
    for (int32_t f = 0; f < m->n_internal_faces; ++f)
        if (m->owner[f] >= m->neighbour[f] || (f > 0 && m->owner[f] < m->owner[f - 1])) return 0;
    return 1;
}

/* z = M^-1 r: DIC (rD holds the reciprocal of the factor's diagonal) or Jacobi (rD = 1/diag).
 * DIC: M = (D + L) D^-1 (D + U), L and U the matrix's off-diagonal parts (-a_f), solved by a forward
 * sweep over the faces in order and a backward sweep in reverse. */
static void precondition(const cdc_mesh *m, int dic, const double *a, const double *rD, const double *r,
                         double *z)
{
    const size_t nc = (size_t)m->n_cells;
    for (size_t c = 0; c < nc; ++c) z[c] = rD[c] * r[c];
    if (!dic) return;
    const int32_t ni = m->n_internal_faces;
    for (int32_t f = 0; f < ni; ++f) z[m->neighbour[f]] += rD[m->neighbour[f]] * a[f] * z[m->owner[f]];
    for (int32_t f = ni - 1; f >= 0; --f) z[m->owner[f]] += rD[m->owner[f]] * a[f] * z[m->neighbour[f]];
}

/* D at a face: 1, or with the D rule the harmonic mean of the cells' D (0.001 in cells larger than 4 d) */
static double face_diffusivity(const cdc_diffusion_params *prm, double volume_p, double volume_n)
{
    if (!prm->d_rule) return 1.0;
    const double lim = 4.0 * prm->particle_diameter;
    const double Dp = cbrt(volume_p) > lim ? 0.001 : 1.0, Dn = cbrt(volume_n) > lim ? 0.001 : 1.0;
    return 2.0 * Dp * Dn / (Dp + Dn);
}

/* The implicit step's matrix A = V/dtau - K (symmetric positive definite) and its preconditioner. */
typedef struct {
    double *a;    /* per internal face: a_f D_f */
    double *rD;   /* per cell: the preconditioner's reciprocal diagonal (DIC's factor, or 1/A_cc) */
    double dtau;  /* pseudo-time step */
    int dic;      /* DIC (1) or Jacobi (0) */
    double tol;   /* relative residual of each solve */
    int max_it;
} implicit_system;

static void setup_system(cdc_context *ctx, const cdc_diffusion_params *prm, implicit_system *sys)
{
    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells, ni = (size_t)m->n_internal_faces;
    double *a = sys->a, *diag = sys->rD;
    /* Face coefficients times D_f. Zhang et al.'s D rule: D = 0.001 in cells larger than 4 d, so
     * that smoothing degenerates to the centroid method there; the face value is the harmonic mean. */
    for (size_t f = 0; f < ni; ++f)
        a[f] = face_diffusivity(prm, m->cell_volumes[m->owner[f]], m->cell_volumes[m->neighbour[f]]) *
               ctx->face_coeff[f];
    const cdc_halo *h = ctx->has_halo ? &ctx->halo : NULL;
    for (int32_t i = 0; h && i < h->n_faces; ++i)
        ctx->halo_coeff.v[i] = face_diffusivity(prm, m->cell_volumes[h->cell[i]], h->nbr_volume[i]) * h->coeff[i];
    const int n_steps = prm->n_steps > 0 ? prm->n_steps : 4;
    sys->tol = prm->tolerance > 0.0 ? prm->tolerance : CDC_DIFFUSION_DEFAULT_TOLERANCE;
    sys->max_it = prm->max_iterations > 0 ? prm->max_iterations : 1000;
    sys->dtau = prm->bandwidth * prm->bandwidth / 4.0 / n_steps;

    for (size_t c = 0; c < nc; ++c) diag[c] = m->cell_volumes[c] / sys->dtau;
    for (size_t f = 0; f < ni; ++f) {
        diag[m->owner[f]] += a[f];
        diag[m->neighbour[f]] += a[f];
    }
    for (int32_t i = 0; h && i < h->n_faces; ++i) diag[h->cell[i]] += ctx->halo_coeff.v[i];
    /* the preconditioner's reciprocal diagonal, in place of the diagonal */
    sys->dic = upper_triangular(m);
    double *rD = diag;
    if (sys->dic)
        for (size_t f = 0; f < ni; ++f) {
            const int32_t o = m->owner[f];
            rD[m->neighbour[f]] -= a[f] * a[f] / rD[o]; /* rD[o] is final: its faces to lower cells came first */
        }
    for (size_t c = 0; c < nc; ++c) rD[c] = 1.0 / rD[c];
}

/* One implicit step: A y = V/dtau x by preconditioned CG from y = x (so r = K x); work is four
 * vectors of cells (r, p, q, z). */
static cdc_status solve_step(cdc_context *ctx, const implicit_system *sys, const double *x, double *y, double *work[4])
{
    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells;
    const double dtau = sys->dtau, *a = sys->a, *rD = sys->rD;
    double *r = work[0], *p = work[1], *q = work[2], *z = work[3];
    cdc_status st;
    memcpy(y, x, nc * sizeof *y);
    if ((st = laplacian(ctx, a, y, r)) != CDC_OK) return st;
    double norms[3] = {0.0, 0.0, 0.0}; /* |b|^2, |r|^2, r.z */
    precondition(m, sys->dic, a, rD, r, p);
    for (size_t c = 0; c < nc; ++c) {
        const double b = m->cell_volumes[c] / dtau * x[c];
        norms[0] += b * b;
        norms[1] += r[c] * r[c];
        norms[2] += r[c] * p[c];
    }
    if ((st = global_sum(ctx, norms, 3)) != CDC_OK) return st;
    const double bnorm = sqrt(norms[0]);
    double rnorm = norms[1], rz = norms[2];
    int it = 0;
    while (sqrt(rnorm) > sys->tol * bnorm) {
        if (++it > sys->max_it)
            return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                            "diffusion: CG did not reach tolerance %g in %d iterations (relative residual %g)",
                            sys->tol, sys->max_it, sqrt(rnorm) / bnorm);
        if ((st = laplacian(ctx, a, p, q)) != CDC_OK) return st;
        double pAp = 0.0;
        for (size_t c = 0; c < nc; ++c) {
            q[c] = m->cell_volumes[c] / dtau * p[c] - q[c];
            pAp += p[c] * q[c];
        }
        if ((st = global_sum(ctx, &pAp, 1)) != CDC_OK) return st;
        const double alpha = rz / pAp;
        double sums[2] = {0.0, 0.0}; /* |r|^2, r.z */
        for (size_t c = 0; c < nc; ++c) {
            y[c] += alpha * p[c];
            r[c] -= alpha * q[c];
        }
        precondition(m, sys->dic, a, rD, r, z);
        for (size_t c = 0; c < nc; ++c) {
            sums[0] += r[c] * r[c];
            sums[1] += r[c] * z[c];
        }
        if ((st = global_sum(ctx, sums, 2)) != CDC_OK) return st;
        rnorm = sums[0];
        const double beta = sums[1] / rz;
        rz = sums[1];
        for (size_t c = 0; c < nc; ++c) p[c] = z[c] + beta * p[c];
    }
    return CDC_OK;
}

cdc_status cdc_diffuse(cdc_context *ctx, const cdc_diffusion_params *prm, double *phi)
{
    if (!ctx || !prm || !phi) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: NULL argument");
    if (!(prm->bandwidth > 0.0) || !isfinite(prm->bandwidth))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: bandwidth %g is invalid (must be > 0)", prm->bandwidth);
    if (prm->n_steps < 0 || prm->max_iterations < 0 || prm->tolerance < 0.0)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: nSteps, maxIterations and tolerance must be >= 0");
    if (prm->d_rule && !(prm->particle_diameter > 0.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the D rule needs a particle diameter > 0");
    cdc_status st = face_coefficients(ctx);
    if (st != CDC_OK) return st;

    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells, ni = (size_t)m->n_internal_faces;
    /* scratch 0..5 and 7 per cell, 6 per internal face */
    _Static_assert(CDC_N_SCRATCH >= 8, "diffusion uses scratch vectors 0..7");
    for (int k = 0; k < 8; ++k)
        if (cdc_dvec_reserve(&ctx->scratch[k], k == 6 ? (ni > 0 ? ni : 1) : nc))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "diffusion: out of memory");
    double *x = ctx->scratch[0].v, *y = ctx->scratch[1].v;
    double *work[4] = {ctx->scratch[2].v, ctx->scratch[3].v, ctx->scratch[4].v, ctx->scratch[7].v};
    implicit_system sys = {ctx->scratch[6].v, ctx->scratch[5].v, 0.0, 0, 0.0, 0};
    setup_system(ctx, prm, &sys);
    const int n_steps = prm->n_steps > 0 ? prm->n_steps : 4;

    /* Work on x so phi is untouched if a solve fails. */
    memcpy(x, phi, nc * sizeof *x);
    for (int step = 0; step < n_steps; ++step) {
        if ((st = solve_step(ctx, &sys, x, y, work)) != CDC_OK) return st;
        /* Flux-form update from the implicit solution: conserves sum(x V) exactly. */
        double *q = work[2];
        if ((st = laplacian(ctx, sys.a, y, q)) != CDC_OK) return st;
        for (size_t c = 0; c < nc; ++c) x[c] += sys.dtau / m->cell_volumes[c] * q[c];
    }
    memcpy(phi, x, nc * sizeof *phi);
    return CDC_OK;
}
