/*
 * exchange.c -- the fluid's momentum sources from the particles' forces, spread with the kernels
 * that gave alpha_p. Spreading is the adjoint of gathering (cdc_gather), so at a fluid velocity whose
 * gathered value is the one the drag used, the fluid receives exactly minus what the particles get:
 * Newton's third law between the phases holds to round-off for every method, here and not in each
 * caller (Zhang et al., Phys. Fluids 35, 113330 (2023), eqs. 16-17; the implicit split as in
 * CFDEM's Ksl, with one coefficient per particle rather than per cell).
 */
#include "internal.h"

#include <string.h>

/* Particle i's implicit contributions, in one pass over its kernel: Ksl += w Kr, KslUs += w Kv and
 * f_fluid += w q. Each array still gets its sums in cdc_spread's order (particle by particle, entry by
 * entry), so the results are bit for bit those of three spreads; one pass reads the kernel once
 * instead of three times (a tenth of a Gaussian coupling: perf of bench's slab). */
static void add_implicit(const int32_t *off, const int32_t *cells, const double *w, int32_t i, double Kr,
                         const double Kv[3], const double q[3], double *Ksl, double *KslUs, double *f_fluid)
{
    for (int32_t e = off[i]; e < off[i + 1]; ++e) {
        const size_t c = (size_t)cells[e];
        const double we = w[e];
        Ksl[c] += we * Kr;
        for (int d = 0; d < 3; ++d) KslUs[3 * c + d] += we * Kv[d];
        for (int d = 0; d < 3; ++d) f_fluid[3 * c + d] += we * q[d];
    }
}

/* Particle i's explicit force density: f_fluid += w q. */
static void add_explicit(const int32_t *off, const int32_t *cells, const double *w, int32_t i, const double q[3],
                         double *f_fluid)
{
    for (int32_t e = off[i]; e < off[i + 1]; ++e)
        for (int d = 0; d < 3; ++d) f_fluid[3 * (size_t)cells[e] + d] += w[e] * q[d];
}

static void per_volume(const cdc_mesh *m, int ncomp, double *out)
{
    for (int32_t c = 0; c < m->n_cells; ++c) {
        const double inv = 1.0 / m->cell_volumes[c];
        for (int d = 0; d < ncomp; ++d) out[(size_t)c * ncomp + d] *= inv;
    }
}

cdc_status cdc_exchange_sources(const cdc_kernels *k, const cdc_exchange_in *in, double *Ksl, double *KslUs,
                                double *f_fluid)
{
    cdc_context *ctx = k ? cdc_kernels_context(k) : NULL;
    const int implicit = in && in->mode == CDC_EXCHANGE_IMPLICIT;
    if (!k || !in || !f_fluid || (implicit && (!Ksl || !KslUs)))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_exchange_sources: NULL argument");
    if (in->mode != CDC_EXCHANGE_IMPLICIT && in->mode != CDC_EXCHANGE_EXPLICIT)
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_exchange_sources: unknown mode %d", (int)in->mode);
    if (in->n != cdc_kernels_count(k))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                        "cdc_exchange_sources: %d particles, the last kernel build had %d (local + ghosts)",
                        (int)in->n, (int)cdc_kernels_count(k));
    if (in->n > 0 && (!in->K || !in->v || !in->u_f))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_exchange_sources: K, v and u_f are needed");
    if (!(in->rho > 0)) return cdc_fail(ctx, CDC_ERR_ARGUMENT, "cdc_exchange_sources: fluid density %g", in->rho);

    const cdc_mesh *m = ctx->mesh;
    const size_t nc = (size_t)m->n_cells;
    const int32_t *off = cdc_kernels_offsets(k), *cells = cdc_kernels_cells(k);
    const double *w = cdc_kernels_weights(k);
    const double rho = in->rho;
    memset(f_fluid, 0, 3 * nc * sizeof *f_fluid);
    if (implicit) {
        memset(Ksl, 0, nc * sizeof *Ksl);
        memset(KslUs, 0, 3 * nc * sizeof *KslUs);
    } else {
        if (Ksl) memset(Ksl, 0, nc * sizeof *Ksl);
        if (KslUs) memset(KslUs, 0, 3 * nc * sizeof *KslUs);
    }
    for (int32_t i = 0; i < in->n; ++i) {
        const double *v = in->v + 3 * (size_t)i, *uf = in->u_f + 3 * (size_t)i;
        const double *uk = in->u_k ? in->u_k + 3 * (size_t)i : NULL;
        const double zero[3] = {0, 0, 0};
        const double *f = in->f ? in->f + 3 * (size_t)i : zero;
        double q[3];
        if (implicit) {
            /* -Ksl U + KslUs: the drag at the fluid's new velocity, K (u - v) per particle */
            const double Kr = in->K[i] / rho;
            double Kv[3];
            for (int d = 0; d < 3; ++d) Kv[d] = Kr * v[d];
            /* the other reacting forces, and, when the drag used a fluid velocity u_f from other
             * (background) kernels, the difference K (u_f - u_k) the implicit part does not carry */
            for (int d = 0; d < 3; ++d) q[d] = -f[d] / rho;
            if (uk)
                for (int d = 0; d < 3; ++d) q[d] -= Kr * (uf[d] - uk[d]);
            add_implicit(off, cells, w, i, Kr, Kv, q, Ksl, KslUs, f_fluid);
        } else {
            for (int d = 0; d < 3; ++d) q[d] = -(in->K[i] * (uf[d] - v[d]) + f[d]) / rho;
            add_explicit(off, cells, w, i, q, f_fluid);
        }
    }
    if (implicit) {
        per_volume(m, 1, Ksl);
        per_volume(m, 3, KslUs);
    }
    per_volume(m, 3, f_fluid);
    return CDC_OK;
}
