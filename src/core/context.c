/*
 * context.c -- mesh checks and the addressing built once per mesh (cell-face, cell-cell, boxes).
 */
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Message of a failed cdc_context_create: the caller has no context to ask, and the core keeps
 * no global mutable state, so the message lives in thread-local storage of the calling thread. */
static _Thread_local char create_msg[CDC_MSG_LEN];

const char *cdc_create_error(void) { return create_msg; }

cdc_status cdc_fail(cdc_context *ctx, cdc_status st, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(ctx ? ctx->msg : create_msg, CDC_MSG_LEN, fmt, ap);
    va_end(ap);
    return st;
}

const char *cdc_last_error(const cdc_context *ctx) { return ctx ? ctx->msg : create_msg; }
const cdc_mesh *cdc_context_mesh(const cdc_context *ctx) { return ctx ? ctx->mesh : NULL; }

/* ---- growable arrays */

int cdc_ivec_reserve(cdc_ivec *a, size_t cap)
{
    if (cap <= a->cap) return 0;
    size_t nc = a->cap ? a->cap : 64;
    while (nc < cap) nc *= 2;
    int32_t *v = realloc(a->v, nc * sizeof *v);
    if (!v) return -1;
    a->v = v;
    a->cap = nc;
    return 0;
}

int cdc_dvec_reserve(cdc_dvec *a, size_t cap)
{
    if (cap <= a->cap) return 0;
    size_t nc = a->cap ? a->cap : 64;
    while (nc < cap) nc *= 2;
    double *v = realloc(a->v, nc * sizeof *v);
    if (!v) return -1;
    a->v = v;
    a->cap = nc;
    return 0;
}

void cdc_ivec_free(cdc_ivec *a) { free(a->v); a->v = NULL; a->n = a->cap = 0; }
void cdc_dvec_free(cdc_dvec *a) { free(a->v); a->v = NULL; a->n = a->cap = 0; }

int32_t cdc_next_stamp(cdc_context *ctx)
{
    if (ctx->stamp_now == INT32_MAX) {
        memset(ctx->stamp, 0, (size_t)ctx->mesh->n_cells * sizeof *ctx->stamp);
        ctx->stamp_now = 0;
    }
    return ++ctx->stamp_now;
}

/* ---- mesh checks */

static cdc_status check_mesh(const cdc_mesh *m)
{
    if (!m) return cdc_fail(NULL, CDC_ERR_ARGUMENT, "mesh: NULL pointer");
    if (m->n_cells <= 0 || m->n_faces <= 0)
        return cdc_fail(NULL, CDC_ERR_MESH, "mesh: empty mesh (%d cells, %d faces)", (int)m->n_cells,
                        (int)m->n_faces);
    if (m->n_internal_faces < 0 || m->n_internal_faces > m->n_faces || m->n_points <= 0)
        return cdc_fail(NULL, CDC_ERR_MESH, "mesh: inconsistent sizes (%d faces, %d internal, %d points)",
                        (int)m->n_faces, (int)m->n_internal_faces, (int)m->n_points);
    if (!m->points || !m->face_point_offsets || !m->face_points || !m->owner ||
        (m->n_internal_faces > 0 && !m->neighbour) || !m->face_centres || !m->face_areas ||
        !m->cell_centres || !m->cell_volumes ||
        (m->n_faces > m->n_internal_faces && !m->boundary_face_kind))
        return cdc_fail(NULL, CDC_ERR_ARGUMENT, "mesh: a required array is NULL");
    for (int32_t f = 0; f < m->n_faces; ++f) {
        if (m->owner[f] < 0 || m->owner[f] >= m->n_cells)
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: face %d has owner %d outside 0..%d", (int)f,
                            (int)m->owner[f], (int)m->n_cells - 1);
        if (f < m->n_internal_faces && (m->neighbour[f] < 0 || m->neighbour[f] >= m->n_cells ||
                                        m->neighbour[f] == m->owner[f]))
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: internal face %d has neighbour %d (owner %d)",
                            (int)f, (int)m->neighbour[f], (int)m->owner[f]);
        const int32_t a = m->face_point_offsets[f], b = m->face_point_offsets[f + 1];
        if (b - a < 3)
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: face %d has %d points (need >= 3)", (int)f,
                            (int)(b - a));
        for (int32_t k = a; k < b; ++k)
            if (m->face_points[k] < 0 || m->face_points[k] >= m->n_points)
                return cdc_fail(NULL, CDC_ERR_MESH, "mesh: face %d refers to point %d outside 0..%d",
                                (int)f, (int)m->face_points[k], (int)m->n_points - 1);
    }
    for (int32_t c = 0; c < m->n_cells; ++c)
        if (!(m->cell_volumes[c] > 0.0) || !isfinite(m->cell_volumes[c]))
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: cell %d has volume %g (must be > 0)", (int)c,
                            m->cell_volumes[c]);
    return CDC_OK;
}

/* CSR from a list of (row, column) pairs given as two passes over the faces. */
static cdc_status build_addressing(cdc_context *ctx)
{
    const cdc_mesh *m = ctx->mesh;
    const int32_t nc = m->n_cells, nf = m->n_faces, ni = m->n_internal_faces;

    ctx->cell_face_offsets = calloc((size_t)nc + 1, sizeof(int32_t));
    ctx->cell_cell_offsets = calloc((size_t)nc + 1, sizeof(int32_t));
    ctx->cell_faces = malloc((size_t)(nf + ni) * sizeof(int32_t));
    ctx->cell_cells = malloc((size_t)(2 * ni > 0 ? 2 * ni : 1) * sizeof(int32_t));
    if (!ctx->cell_face_offsets || !ctx->cell_cell_offsets || !ctx->cell_faces || !ctx->cell_cells)
        return cdc_fail(NULL, CDC_ERR_NOMEM, "mesh: out of memory building cell addressing");

    for (int32_t f = 0; f < nf; ++f) {
        ctx->cell_face_offsets[m->owner[f] + 1]++;
        if (f < ni) {
            ctx->cell_face_offsets[m->neighbour[f] + 1]++;
            ctx->cell_cell_offsets[m->owner[f] + 1]++;
            ctx->cell_cell_offsets[m->neighbour[f] + 1]++;
        }
    }
    for (int32_t c = 0; c < nc; ++c) {
        ctx->cell_face_offsets[c + 1] += ctx->cell_face_offsets[c];
        ctx->cell_cell_offsets[c + 1] += ctx->cell_cell_offsets[c];
    }
    int32_t *fill_f = calloc((size_t)nc, sizeof(int32_t));
    int32_t *fill_c = calloc((size_t)nc, sizeof(int32_t));
    if (!fill_f || !fill_c) {
        free(fill_f);
        free(fill_c);
        return cdc_fail(NULL, CDC_ERR_NOMEM, "mesh: out of memory building cell addressing");
    }
    for (int32_t f = 0; f < nf; ++f) {
        const int32_t o = m->owner[f];
        ctx->cell_faces[ctx->cell_face_offsets[o] + fill_f[o]++] = f;
        if (f < ni) {
            const int32_t n = m->neighbour[f];
            ctx->cell_faces[ctx->cell_face_offsets[n] + fill_f[n]++] = f;
            ctx->cell_cells[ctx->cell_cell_offsets[o] + fill_c[o]++] = n;
            ctx->cell_cells[ctx->cell_cell_offsets[n] + fill_c[n]++] = o;
        }
    }
    free(fill_f);
    free(fill_c);
    for (int32_t c = 0; c < nc; ++c)
        if (ctx->cell_face_offsets[c + 1] - ctx->cell_face_offsets[c] < 4)
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: cell %d has %d faces (need >= 4)", (int)c,
                            (int)(ctx->cell_face_offsets[c + 1] - ctx->cell_face_offsets[c]));
    return CDC_OK;
}

/* Bounding boxes from the face points; a cell "is a box" when its volume equals its bounding
 * box's volume (a convex cell inside its box with the same volume is the box). Also the faces'
 * unit normals and the bound on a location walk. */
static cdc_status build_boxes(cdc_context *ctx)
{
    const cdc_mesh *m = ctx->mesh;
    for (int32_t f = 0; f < m->n_faces; ++f) {
        const double *S = m->face_areas + 3 * (size_t)f;
        const double mag = sqrt(S[0] * S[0] + S[1] * S[1] + S[2] * S[2]);
        if (!(mag > 0.0) || !isfinite(mag))
            return cdc_fail(NULL, CDC_ERR_MESH, "mesh: face %d has area %g (must be > 0)", (int)f, mag);
        for (int d = 0; d < 3; ++d) ctx->face_unit_normal[3 * (size_t)f + d] = S[d] / mag;
    }
    ctx->walk_max_steps = 4 * (int32_t)cbrt((double)m->n_cells) + 64;
    for (int k = 0; k < 3; ++k) {
        ctx->mesh_lo[k] = INFINITY;
        ctx->mesh_hi[k] = -INFINITY;
    }
    ctx->total_volume = 0.0;
    for (int32_t c = 0; c < m->n_cells; ++c) {
        double *bb = ctx->cell_bbox + 6 * (size_t)c;
        bb[0] = bb[1] = bb[2] = INFINITY;
        bb[3] = bb[4] = bb[5] = -INFINITY;
        for (int32_t q = ctx->cell_face_offsets[c]; q < ctx->cell_face_offsets[c + 1]; ++q) {
            const int32_t f = ctx->cell_faces[q];
            for (int32_t k = m->face_point_offsets[f]; k < m->face_point_offsets[f + 1]; ++k) {
                const double *x = m->points + 3 * (size_t)m->face_points[k];
                for (int d = 0; d < 3; ++d) {
                    if (x[d] < bb[d]) bb[d] = x[d];
                    if (x[d] > bb[3 + d]) bb[3 + d] = x[d];
                }
            }
        }
        const double bv = (bb[3] - bb[0]) * (bb[4] - bb[1]) * (bb[5] - bb[2]);
        ctx->cell_is_box[c] = fabs(bv - m->cell_volumes[c]) <= 1e-9 * bv;
        for (int d = 0; d < 3; ++d) {
            if (bb[d] < ctx->mesh_lo[d]) ctx->mesh_lo[d] = bb[d];
            if (bb[3 + d] > ctx->mesh_hi[d]) ctx->mesh_hi[d] = bb[3 + d];
        }
        ctx->total_volume += m->cell_volumes[c];
        for (int d = 0; d < 3; ++d) ctx->cell_xv[4 * (size_t)c + d] = m->cell_centres[3 * (size_t)c + d];
        ctx->cell_xv[4 * (size_t)c + 3] = m->cell_volumes[c];
    }
    return CDC_OK;
}

cdc_status cdc_context_create(const cdc_mesh *mesh, cdc_context **out)
{
    if (!out) return cdc_fail(NULL, CDC_ERR_ARGUMENT, "cdc_context_create: NULL output pointer");
    cdc_status st = check_mesh(mesh);
    if (st != CDC_OK) return st;

    cdc_context *ctx = calloc(1, sizeof *ctx);
    if (!ctx) return cdc_fail(NULL, CDC_ERR_NOMEM, "out of memory creating the context");
    ctx->mesh = mesh;
    st = build_addressing(ctx);
    if (st == CDC_OK) {
        const size_t nc = (size_t)mesh->n_cells;
        ctx->cell_bbox = malloc(6 * nc * sizeof(double));
        ctx->cell_xv = malloc(4 * nc * sizeof(double));
        ctx->cell_is_box = calloc(nc, 1);
        ctx->stamp = calloc(nc, sizeof(int32_t));
        ctx->face_unit_normal = malloc(3 * (size_t)mesh->n_faces * sizeof(double));
        if (!ctx->cell_bbox || !ctx->cell_xv || !ctx->cell_is_box || !ctx->stamp || !ctx->face_unit_normal)
            st = cdc_fail(NULL, CDC_ERR_NOMEM, "mesh: out of memory for cell boxes");
        else
            st = build_boxes(ctx);
    }
    if (st == CDC_OK && cdc_wall_facets_from_mesh(ctx) != CDC_OK) {
        st = cdc_fail(NULL, CDC_ERR_NOMEM, "mesh: %s", ctx->msg);
    }
    if (st != CDC_OK) {
        cdc_context_destroy(ctx);
        return st;
    }
    *out = ctx;
    return CDC_OK;
}

void cdc_context_destroy(cdc_context *ctx)
{
    if (!ctx) return;
    free(ctx->cell_face_offsets);
    free(ctx->cell_faces);
    free(ctx->cell_cell_offsets);
    free(ctx->cell_cells);
    free(ctx->cell_bbox);
    free(ctx->cell_xv);
    free(ctx->cell_is_box);
    free(ctx->face_unit_normal);
    free(ctx->facets);
    free(ctx->facet_offsets);
    free(ctx->facet_items);
    free(ctx->facet_plane);
    free(ctx->bin_offsets);
    free(ctx->bin_cells);
    free(ctx->stamp);
    cdc_ivec_free(&ctx->queue);
    cdc_ivec_free(&ctx->near_cells);
    free(ctx->face_coeff);
    for (int k = 0; k < CDC_N_SCRATCH; ++k) cdc_dvec_free(&ctx->scratch[k]);
    cdc_dvec_free(&ctx->class_q);
    cdc_dvec_free(&ctx->class_field);
    cdc_dvec_free(&ctx->class_sum);
    cdc_dvec_free(&ctx->halo_coeff);
    cdc_dvec_free(&ctx->halo_nbr);
    cdc_dvec_free(&ctx->halo_fields);
    cdc_dvec_free(&ctx->halo_work);
    free(ctx);
}

cdc_status cdc_context_set_halo(cdc_context *ctx, const cdc_halo *halo)
{
    if (!ctx) return CDC_ERR_ARGUMENT;
    ctx->has_halo = 0;
    if (!halo) return CDC_OK;
    if (halo->n_faces < 0 || !halo->exchange || !halo->sum ||
        (halo->n_faces > 0 && (!halo->cell || !halo->coeff || !halo->nbr_volume)))
        return cdc_fail(ctx, CDC_ERR_ARGUMENT, "halo: missing faces, coefficients, volumes or callbacks");
    for (int32_t i = 0; i < halo->n_faces; ++i)
        if (halo->cell[i] < 0 || halo->cell[i] >= ctx->mesh->n_cells || !(halo->coeff[i] > 0.0) ||
            !(halo->nbr_volume[i] > 0.0))
            return cdc_fail(ctx, CDC_ERR_ARGUMENT,
                            "halo: processor face %d has cell %d, coefficient %g, neighbour volume %g", (int)i,
                            (int)halo->cell[i], halo->coeff[i], halo->nbr_volume[i]);
    if (cdc_dvec_reserve(&ctx->halo_coeff, (size_t)halo->n_faces + 1) ||
        cdc_dvec_reserve(&ctx->halo_nbr, (size_t)halo->n_faces + 1))
        return cdc_fail(ctx, CDC_ERR_NOMEM, "halo: out of memory");
    ctx->halo = *halo;
    ctx->has_halo = 1;
    return CDC_OK;
}
