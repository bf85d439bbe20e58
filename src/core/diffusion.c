/*
 * diffusion.c -- diffusion-based smoothing (Sun & Xiao; Zhang et al., Phys. Fluids 35, 113330
 * (2023), §II.C, eq. 7).
 *
 * Formulation: d(phi)/dtau = div(D grad phi) in pseudo-time tau, zero flux through every boundary
 * face (walls, inlets, outlets alike, as the paper requires for conservation), integrated to
 * T = b^2/4 so that, with D = 1, a point source spreads like the Gaussian kernel exp(-r^2/b^2).
 * Finite volumes, two-point flux a_f (phi_N - phi_P) with a_f = D_f |S_f| / |C_N - C_P| (no
 * non-orthogonal correction: exact on orthogonal meshes, conservative on any mesh). Implicit Euler
 * in n_steps equal steps, each solved by Jacobi-preconditioned conjugate gradients.
 *
 * Conservation to round-off whatever the solver tolerance: the step's final value is written in
 * flux form, phi_new = phi_old + dtau/V * sum_f a_f (phi*_N - phi*_P), where phi* is the CG
 * solution. Each face flux leaves one cell and enters the other, so sum(phi V) cannot change.
 *
 * Processor faces are zero-flux here: the core sees one rank's mesh. (Parallel smoothing needs a
 * halo exchange by the caller.)
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

/* y = K x, the (negative semi-definite) Laplacian times volume: y_P = sum_f a_f (x_N - x_P). */
static void laplacian(const cdc_mesh *m, const double *a, const double *x, double *y)
{
    memset(y, 0, (size_t)m->n_cells * sizeof *y);
    for (int32_t f = 0; f < m->n_internal_faces; ++f) {
        const int32_t o = m->owner[f], n = m->neighbour[f];
        const double flux = a[f] * (x[n] - x[o]);
        y[o] += flux;
        y[n] -= flux;
    }
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
    for (int k = 0; k < CDC_N_SCRATCH; ++k)
        if (cdc_dvec_reserve(&ctx->scratch[k], k == CDC_N_SCRATCH - 1 ? (ni > 0 ? ni : 1) : nc))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "diffusion: out of memory");
    double *x = ctx->scratch[0].v, *y = ctx->scratch[1].v, *r = ctx->scratch[2].v, *p = ctx->scratch[3].v,
           *q = ctx->scratch[4].v, *diag = ctx->scratch[5].v, *a = ctx->scratch[6].v;

    /* Face coefficients times D_f. The seed's D rule: D = 0.001 in cells larger than 4 d, so that
     * smoothing degenerates to the centroid method there; the face value is the harmonic mean. */
    for (size_t f = 0; f < ni; ++f) {
        double D = 1.0;
        if (prm->d_rule) {
            const double lim = 4.0 * prm->particle_diameter;
            const double Do = cbrt(m->cell_volumes[m->owner[f]]) > lim ? 0.001 : 1.0;
            const double Dn = cbrt(m->cell_volumes[m->neighbour[f]]) > lim ? 0.001 : 1.0;
            D = 2.0 * Do * Dn / (Do + Dn);
        }
        a[f] = D * ctx->face_coeff[f];
    }
    const int n_steps = prm->n_steps > 0 ? prm->n_steps : 4;
    const double tol = prm->tolerance > 0.0 ? prm->tolerance : 1e-10;
    const int max_it = prm->max_iterations > 0 ? prm->max_iterations : 1000;
    const double dtau = prm->bandwidth * prm->bandwidth / 4.0 / n_steps;

    /* Matrix A = V/dtau - K (symmetric positive definite); its diagonal for Jacobi. */
    for (size_t c = 0; c < nc; ++c) diag[c] = m->cell_volumes[c] / dtau;
    for (size_t f = 0; f < ni; ++f) {
        diag[m->owner[f]] += a[f];
        diag[m->neighbour[f]] += a[f];
    }

    /* Work on x so phi is untouched if a solve fails. */
    memcpy(x, phi, nc * sizeof *x);
    for (int step = 0; step < n_steps; ++step) {
        /* Solve A y = V/dtau x by preconditioned CG from y = x (so r = K x). */
        memcpy(y, x, nc * sizeof *y);
        laplacian(m, a, y, r);
        double bnorm = 0.0, rnorm = 0.0, rz = 0.0;
        for (size_t c = 0; c < nc; ++c) {
            const double b = m->cell_volumes[c] / dtau * x[c];
            bnorm += b * b;
            rnorm += r[c] * r[c];
            p[c] = r[c] / diag[c];
            rz += r[c] * p[c];
        }
        bnorm = sqrt(bnorm);
        int it = 0;
        while (sqrt(rnorm) > tol * bnorm) {
            if (++it > max_it)
                return cdc_fail(ctx, CDC_ERR_NOT_CONVERGED,
                                "diffusion: CG did not reach tolerance %g in %d iterations (relative residual %g)",
                                tol, max_it, sqrt(rnorm) / bnorm);
            laplacian(m, a, p, q);
            double pAp = 0.0;
            for (size_t c = 0; c < nc; ++c) {
                q[c] = m->cell_volumes[c] / dtau * p[c] - q[c];
                pAp += p[c] * q[c];
            }
            const double alpha = rz / pAp;
            double rz_new = 0.0;
            rnorm = 0.0;
            for (size_t c = 0; c < nc; ++c) {
                y[c] += alpha * p[c];
                r[c] -= alpha * q[c];
                rnorm += r[c] * r[c];
                rz_new += r[c] * r[c] / diag[c];
            }
            const double beta = rz_new / rz;
            rz = rz_new;
            for (size_t c = 0; c < nc; ++c) p[c] = r[c] / diag[c] + beta * p[c];
        }
        /* Flux-form update from the implicit solution: conserves sum(x V) exactly. */
        laplacian(m, a, y, q);
        for (size_t c = 0; c < nc; ++c) x[c] += dtau / m->cell_volumes[c] * q[c];
    }
    memcpy(phi, x, nc * sizeof *phi);
    return CDC_OK;
}
