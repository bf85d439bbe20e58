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
 * internal faces and, with a halo, processor faces (coefficients ctx->halo_coeff). x and y hold k
 * fields side by side (x[c k + d]); each field's sums run in the same order as for one field alone. */
static cdc_status laplacian(cdc_context *ctx, const double *a, const double *x, double *y, int k)
{
    const cdc_mesh *m = ctx->mesh;
    memset(y, 0, (size_t)m->n_cells * (size_t)k * sizeof *y);
    for (int32_t f = 0; f < m->n_internal_faces; ++f) {
        const size_t o = (size_t)m->owner[f] * (size_t)k, n = (size_t)m->neighbour[f] * (size_t)k;
        for (int d = 0; d < k; ++d) {
            const double flux = a[f] * (x[n + d] - x[o + d]);
            y[o + d] += flux;
            y[n + d] -= flux;
        }
    }
    if (!ctx->has_halo) return CDC_OK;
    const cdc_halo *h = &ctx->halo;
    double *xn = ctx->halo_nbr.v;
    if (k == 1) {
        if (h->exchange(h->user, x, xn)) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the halo exchange failed");
    } else {
        /* the caller's exchange carries one value per cell: one exchange per field */
        const size_t nc = (size_t)m->n_cells;
        double *cells = ctx->halo_fields.v, *nbr = cells + nc;
        for (int d = 0; d < k; ++d) {
            for (size_t c = 0; c < nc; ++c) cells[c] = x[c * (size_t)k + (size_t)d];
            if (h->exchange(h->user, cells, nbr))
                return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the halo exchange failed");
            for (int32_t i = 0; i < h->n_faces; ++i) xn[(size_t)i * (size_t)k + (size_t)d] = nbr[i];
        }
    }
    for (int32_t i = 0; i < h->n_faces; ++i) {
        const size_t c = (size_t)h->cell[i] * (size_t)k, j = (size_t)i * (size_t)k;
        for (int d = 0; d < k; ++d) y[c + d] += ctx->halo_coeff.v[i] * (xn[j + d] - x[c + d]);
    }
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

/* z = M^-1 r: DIC (rD holds the reciprocal of the factor's diagonal) or Jacobi (rD = 1/diag), for k
 * fields side by side. DIC: M = (D + L) D^-1 (D + U), L and U the matrix's off-diagonal parts (-a_f),
 * solved by a forward sweep over the faces in order and a backward sweep in reverse. */
static void precondition(const cdc_mesh *m, int dic, const double *a, const double *rD, const double *r,
                         double *z, int k)
{
    const size_t nc = (size_t)m->n_cells, K = (size_t)k;
    for (size_t c = 0; c < nc; ++c)
        for (size_t d = 0; d < K; ++d) z[c * K + d] = rD[c] * r[c * K + d];
    if (!dic) return;
    const int32_t ni = m->n_internal_faces;
    for (int32_t f = 0; f < ni; ++f) {
        const size_t o = (size_t)m->owner[f], n = (size_t)m->neighbour[f];
        for (size_t d = 0; d < K; ++d) z[n * K + d] += rD[n] * a[f] * z[o * K + d];
    }
    for (int32_t f = ni - 1; f >= 0; --f) {
        const size_t o = (size_t)m->owner[f], n = (size_t)m->neighbour[f];
        for (size_t d = 0; d < K; ++d) z[o * K + d] += rD[o] * a[f] * z[n * K + d];
    }
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

/* One implicit step: A y = V/dtau x by preconditioned CG from y = x (so r = K x), for k fields side by
 * side: the fields share the matrix and each sweep over the faces, while each has its own CG scalars
 * and stops when it converges (its values then stay as they are), so every field gets the bits its
 * solve alone would give. Work is four vectors of k values per cell (r, p, q, z). */
static cdc_status solve_step(cdc_context *ctx, const implicit_system *sys, const double *x, double *y, double *work[4],
                             int k)
{
    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells, K = (size_t)k;
    const double dtau = sys->dtau, *a = sys->a, *rD = sys->rD;
    double *r = work[0], *p = work[1], *q = work[2], *z = work[3];
    cdc_status st;
    memcpy(y, x, nc * K * sizeof *y);
    if ((st = laplacian(ctx, a, y, r, k)) != CDC_OK) return st;
    double norms[3 * CDC_DIFFUSE_MAX_FIELDS] = {0.0}; /* per field: |b|^2, |r|^2, r.z */
    precondition(m, sys->dic, a, rD, r, p, k);
    for (size_t c = 0; c < nc; ++c)
        for (size_t d = 0; d < K; ++d) {
            const double b = m->cell_volumes[c] / dtau * x[c * K + d];
            norms[3 * d] += b * b;
            norms[3 * d + 1] += r[c * K + d] * r[c * K + d];
            norms[3 * d + 2] += r[c * K + d] * p[c * K + d];
        }
    if ((st = global_sum(ctx, norms, 3 * k)) != CDC_OK) return st;
    double bnorm[CDC_DIFFUSE_MAX_FIELDS], rnorm[CDC_DIFFUSE_MAX_FIELDS], rz[CDC_DIFFUSE_MAX_FIELDS];
    double alpha[CDC_DIFFUSE_MAX_FIELDS], beta[CDC_DIFFUSE_MAX_FIELDS];
    int active[CDC_DIFFUSE_MAX_FIELDS];
    for (size_t d = 0; d < K; ++d) {
        bnorm[d] = sqrt(norms[3 * d]);
        rnorm[d] = norms[3 * d + 1];
        rz[d] = norms[3 * d + 2];
    }
    for (int it = 1;; ++it) {
        int n_active = 0;
        for (size_t d = 0; d < K; ++d) {
            active[d] = sqrt(rnorm[d]) > sys->tol * bnorm[d];
            n_active += active[d];
        }
        if (n_active == 0) break;
        if (it > sys->max_it) {
            int worst = -1; /* the active field furthest from its tolerance (an active field has bnorm > 0) */
            for (size_t d = 0; d < K; ++d)
                if (active[d] && (worst < 0 || sqrt(rnorm[d]) / bnorm[d] > sqrt(rnorm[worst]) / bnorm[worst]))
                    worst = (int)d;
            if (k == 1)
                return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                                "diffusion: CG did not reach tolerance %g in %d iterations (relative residual %g)",
                                sys->tol, sys->max_it, sqrt(rnorm[worst]) / bnorm[worst]);
            return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                            "diffusion: CG did not reach tolerance %g in %d iterations (relative residual %g of "
                            "field %d of the %d smoothed together)",
                            sys->tol, sys->max_it, sqrt(rnorm[worst]) / bnorm[worst], worst, k);
        }
        if ((st = laplacian(ctx, a, p, q, k)) != CDC_OK) return st;
        double pAp[CDC_DIFFUSE_MAX_FIELDS] = {0.0};
        for (size_t c = 0; c < nc; ++c)
            for (size_t d = 0; d < K; ++d) {
                q[c * K + d] = m->cell_volumes[c] / dtau * p[c * K + d] - q[c * K + d];
                pAp[d] += p[c * K + d] * q[c * K + d];
            }
        if ((st = global_sum(ctx, pAp, k)) != CDC_OK) return st;
        for (size_t d = 0; d < K; ++d) alpha[d] = active[d] ? rz[d] / pAp[d] : 0.0;
        for (size_t c = 0; c < nc; ++c)
            for (size_t d = 0; d < K; ++d)
                if (active[d]) {
                    y[c * K + d] += alpha[d] * p[c * K + d];
                    r[c * K + d] -= alpha[d] * q[c * K + d];
                }
        precondition(m, sys->dic, a, rD, r, z, k);
        double sums[2 * CDC_DIFFUSE_MAX_FIELDS] = {0.0}; /* per field: |r|^2, r.z */
        for (size_t c = 0; c < nc; ++c)
            for (size_t d = 0; d < K; ++d) {
                sums[2 * d] += r[c * K + d] * r[c * K + d];
                sums[2 * d + 1] += r[c * K + d] * z[c * K + d];
            }
        if ((st = global_sum(ctx, sums, 2 * k)) != CDC_OK) return st;
        for (size_t d = 0; d < K; ++d)
            if (active[d]) {
                rnorm[d] = sums[2 * d];
                beta[d] = sums[2 * d + 1] / rz[d];
                rz[d] = sums[2 * d + 1];
            }
        for (size_t c = 0; c < nc; ++c)
            for (size_t d = 0; d < K; ++d)
                if (active[d]) p[c * K + d] = z[c * K + d] + beta[d] * p[c * K + d];
    }
    return CDC_OK;
}

cdc_status cdc_diffuse(cdc_context *ctx, const cdc_diffusion_params *prm, double *phi)
{
    return cdc_diffuse_fields(ctx, prm, phi, 1);
}

cdc_status cdc_diffuse_fields(cdc_context *ctx, const cdc_diffusion_params *prm, double *phi, int n_fields)
{
    if (!ctx || !prm || !phi) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: NULL argument");
    if (n_fields < 1 || n_fields > CDC_DIFFUSE_MAX_FIELDS)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: %d fields at once (1 to %d)", n_fields,
                        CDC_DIFFUSE_MAX_FIELDS);
    if (!(prm->bandwidth > 0.0) || !isfinite(prm->bandwidth))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: bandwidth %g is invalid (must be > 0)", prm->bandwidth);
    if (prm->n_steps < 0 || prm->max_iterations < 0 || prm->tolerance < 0.0)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: nSteps, maxIterations and tolerance must be >= 0");
    if (prm->d_rule && !(prm->particle_diameter > 0.0))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "diffusion: the D rule needs a particle diameter > 0");
    cdc_status st = face_coefficients(ctx);
    if (st != CDC_OK) return st;

    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells, ni = (size_t)m->n_internal_faces, K = (size_t)n_fields;
    /* scratch 0..5 and 7 per cell (0..4 and 7 with the fields' values), 6 per internal face */
    _Static_assert(CDC_N_SCRATCH >= 8, "diffusion uses scratch vectors 0..7");
    for (int s = 0; s < 8; ++s)
        if (cdc_dvec_reserve(&ctx->scratch[s], s == 6 ? (ni > 0 ? ni : 1) : s == 5 ? nc : nc * K))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "diffusion: out of memory");
    if (ctx->has_halo && n_fields > 1 &&
        (cdc_dvec_reserve(&ctx->halo_nbr, (size_t)ctx->halo.n_faces * K + 1) ||
         cdc_dvec_reserve(&ctx->halo_fields, nc + (size_t)ctx->halo.n_faces + 1)))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "diffusion: out of memory");
    double *x = ctx->scratch[0].v, *y = ctx->scratch[1].v;
    double *work[4] = {ctx->scratch[2].v, ctx->scratch[3].v, ctx->scratch[4].v, ctx->scratch[7].v};
    implicit_system sys = {ctx->scratch[6].v, ctx->scratch[5].v, 0.0, 0, 0.0, 0};
    setup_system(ctx, prm, &sys);
    const int n_steps = prm->n_steps > 0 ? prm->n_steps : 4;

    /* Work on x so phi is untouched if a solve fails. */
    memcpy(x, phi, nc * K * sizeof *x);
    for (int step = 0; step < n_steps; ++step) {
        if ((st = solve_step(ctx, &sys, x, y, work, n_fields)) != CDC_OK) return st;
        /* Flux-form update from the implicit solution: conserves sum(x V) exactly. */
        double *q = work[2];
        if ((st = laplacian(ctx, sys.a, y, q, n_fields)) != CDC_OK) return st;
        for (size_t c = 0; c < nc; ++c)
            for (size_t d = 0; d < K; ++d) x[c * K + d] += sys.dtau / m->cell_volumes[c] * q[c * K + d];
    }
    memcpy(phi, x, nc * K * sizeof *phi);
    return CDC_OK;
}
