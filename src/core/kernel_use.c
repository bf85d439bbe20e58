/*
 * kernel_use.c -- what the kernels are for: alpha_p, spreading particle quantities to the cells and
 * gathering cell fields at the particles (adjoint operations), and the particles that reach beyond
 * the mesh.
 */
#include "internal.h"

#include <math.h>
#include <string.h>

/* How far along the unit direction e the particle reaches beyond the mesh, as a fraction of r
 * (0 if the end x + r e is in a cell): the boundary is bracketed between the centre (inside) and
 * the end (outside) and found by bisection. On one rank of a decomposed mesh a particle near the
 * processor boundary reaches into the neighbour's cells, not out of the domain: a path that leaves
 * through a processor face counts 0 (what lies beyond it is the neighbour rank's mesh). */
static cdc_status reach_beyond(cdc_context *ctx, const double x[3], double r, const double e[3], int32_t host,
                               double *fraction)
{
    double y[3] = {x[0] + r * e[0], x[1] + r * e[1], x[2] + r * e[2]};
    int32_t c;
    cdc_status st = cdc_locate_point(ctx, y, host, &c);
    *fraction = 0.0;
    if (st != CDC_OK || c >= 0) return st;
    double in = 0.0, out = 1.0; /* along the axis, in radii */
    int32_t last_in = host;     /* the cell of the point at `in` (the centre's host to start with) */
    while (out - in > 1e-6) {
        const double mid = 0.5 * (in + out);
        for (int d = 0; d < 3; ++d) y[d] = x[d] + mid * r * e[d];
        st = cdc_locate_point(ctx, y, host, &c);
        if (st != CDC_OK) return st;
        if (c >= 0) {
            in = mid;
            last_in = c;
        } else {
            out = mid;
        }
    }
    /* the face the path leaves the last inside cell through, seen from the first outside point */
    const cdc_mesh *m = ctx->mesh;
    for (int d = 0; d < 3; ++d) y[d] = x[d] + out * r * e[d];
    const int32_t f = cdc_exit_face(ctx, last_in, y);
    if (f >= m->n_internal_faces && m->boundary_face_kind[f - m->n_internal_faces] == CDC_FACE_PROCESSOR)
        return CDC_OK;
    *fraction = 1.0 - in;
    return CDC_OK;
}

cdc_status cdc_kernels_partly_outside(const cdc_kernels *k, const cdc_particles *p, int32_t *count,
                                      double *depth, int64_t *id)
{
    if (!k || !p || !count || !depth || !id) return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT,
                                                             "cdc_kernels_partly_outside: NULL argument");
    *count = 0;
    *depth = 0.0;
    *id = -1;
    const int32_t n = p->n < k->n_local ? p->n : k->n_local;
    for (int32_t i = 0; i < n; ++i) {
        const int32_t host = k->hosts.v[i];
        if (host < 0) continue; /* outside altogether: cdc_kernels_outside */
        const double *x = p->position + 3 * (size_t)i;
        double deepest = 0.0;
        for (int a = 0; a < 6; ++a) {
            double e[3] = {0.0, 0.0, 0.0}, f;
            e[a / 2] = (a % 2) ? -1.0 : 1.0;
            cdc_status st = reach_beyond(k->ctx, x, p->radius[i], e, host, &f);
            if (st != CDC_OK) return st;
            if (f > deepest) deepest = f;
        }
        if (deepest > 0.0) {
            ++*count;
            if (deepest > *depth) {
                *depth = deepest;
                *id = cdc_particle_id(p, i);
            }
        }
    }
    return CDC_OK;
}

cdc_status cdc_spread(const cdc_kernels *k, const double *q, int ncomp, double *out)
{
    /* a rank may hold no particles: then q may be NULL */
    if (!k || (!q && k->n > 0) || !out || ncomp <= 0)
        return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT, "cdc_spread: NULL argument or ncomp <= 0");
    const cdc_mesh *m = k->ctx->mesh;
    memset(out, 0, (size_t)m->n_cells * (size_t)ncomp * sizeof *out);
    const int32_t *off = k->offsets.v;
    for (int32_t i = 0; i < k->n; ++i)
        for (int32_t e = off[i]; e < off[i + 1]; ++e) {
            const int32_t c = k->cells.v[e];
            const double w = k->weights.v[e];
            for (int d = 0; d < ncomp; ++d) out[(size_t)c * ncomp + d] += w * q[(size_t)i * ncomp + d];
        }
    for (int32_t c = 0; c < m->n_cells; ++c) {
        const double inv = 1.0 / m->cell_volumes[c];
        for (int d = 0; d < ncomp; ++d) out[(size_t)c * ncomp + d] *= inv;
    }
    return CDC_OK;
}

cdc_status cdc_alpha_p(const cdc_kernels *k, const cdc_particles *p, double *alpha_p)
{
    if (!k || !p || !alpha_p || p->n != k->n)
        return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT,
                        "cdc_alpha_p: NULL argument or particle count differs from the last build");
    /* Spread particle volumes; reuse raw_weights as the per-particle volume buffer. */
    cdc_kernels *mk = (cdc_kernels *)k;
    if (cdc_dvec_reserve(&mk->raw_weights, (size_t)p->n + 1))
        return cdc_fail(k->ctx, CDC_ERR_NOMEM, "out of memory in cdc_alpha_p");
    for (int32_t i = 0; i < p->n; ++i)
        mk->raw_weights.v[i] = 4.0 / 3.0 * CDC_PI * p->radius[i] * p->radius[i] * p->radius[i];
    return cdc_spread(k, mk->raw_weights.v, 1, alpha_p);
}

cdc_status cdc_gather(const cdc_kernels *k, const double *field, int ncomp, double *out)
{
    if (!k || !field || (!out && k->n > 0) || ncomp <= 0)
        return cdc_fail(k ? k->ctx : NULL, CDC_ERR_ARGUMENT, "cdc_gather: NULL argument or ncomp <= 0");
    /* The adjoint of cdc_spread: what a particle sees is the kernel-weighted mean of the field.
     * For kernels uniform in volume fraction (w_c = V_c / sum V_c) this is eqs. 21-22. */
    const int32_t *off = k->offsets.v;
    for (int32_t i = 0; i < k->n; ++i) {
        double *o = out + (size_t)i * ncomp;
        for (int d = 0; d < ncomp; ++d) o[d] = 0.0;
        for (int32_t e = off[i]; e < off[i + 1]; ++e) {
            const int32_t c = k->cells.v[e];
            const double w = k->weights.v[e];
            for (int d = 0; d < ncomp; ++d) o[d] += w * field[(size_t)c * ncomp + d];
        }
    }
    return CDC_OK;
}
