/* box_mesh.c -- see box_mesh.h. */
#include "box_mesh.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

void box_mesh_geometry(cdc_mesh *m, double *fc, double *fa, double *cc, double *cv)
{
    for (int32_t f = 0; f < m->n_faces; ++f) {
        const int32_t a = m->face_point_offsets[f], b = m->face_point_offsets[f + 1], n = b - a;
        double mid[3] = {0, 0, 0};
        for (int32_t k = a; k < b; ++k)
            for (int d = 0; d < 3; ++d) mid[d] += m->points[3 * (size_t)m->face_points[k] + d] / n;
        double S[3] = {0, 0, 0}, C[3] = {0, 0, 0}, sumA = 0.0;
        for (int32_t k = 0; k < n; ++k) {
            const double *p0 = m->points + 3 * (size_t)m->face_points[a + k];
            const double *p1 = m->points + 3 * (size_t)m->face_points[a + (k + 1) % n];
            double e0[3], e1[3], s[3];
            for (int d = 0; d < 3; ++d) {
                e0[d] = p0[d] - mid[d];
                e1[d] = p1[d] - mid[d];
            }
            cross(e0, e1, s);
            const double A = 0.5 * sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
            for (int d = 0; d < 3; ++d) {
                S[d] += 0.5 * s[d];
                C[d] += A * (p0[d] + p1[d] + mid[d]) / 3.0;
            }
            sumA += A;
        }
        for (int d = 0; d < 3; ++d) {
            fa[3 * (size_t)f + d] = S[d];
            fc[3 * (size_t)f + d] = sumA > 0 ? C[d] / sumA : mid[d];
        }
    }
    /* cells: pyramids from the mean of the cell's face centres */
    double *est = calloc(3 * (size_t)m->n_cells, sizeof(double));
    int32_t *nf = calloc((size_t)m->n_cells, sizeof(int32_t));
    for (int32_t f = 0; f < m->n_faces; ++f) {
        const int32_t cs[2] = {m->owner[f], f < m->n_internal_faces ? m->neighbour[f] : -1};
        for (int s = 0; s < 2; ++s)
            if (cs[s] >= 0) {
                nf[cs[s]]++;
                for (int d = 0; d < 3; ++d) est[3 * (size_t)cs[s] + d] += fc[3 * (size_t)f + d];
            }
    }
    for (int32_t c = 0; c < m->n_cells; ++c)
        for (int d = 0; d < 3; ++d) est[3 * (size_t)c + d] /= nf[c];
    memset(cc, 0, 3 * (size_t)m->n_cells * sizeof(double));
    memset(cv, 0, (size_t)m->n_cells * sizeof(double));
    for (int32_t f = 0; f < m->n_faces; ++f) {
        const int32_t cs[2] = {m->owner[f], f < m->n_internal_faces ? m->neighbour[f] : -1};
        for (int s = 0; s < 2; ++s) {
            const int32_t c = cs[s];
            if (c < 0) continue;
            const double sign = s == 0 ? 1.0 : -1.0;
            double h = 0.0;
            for (int d = 0; d < 3; ++d)
                h += (fc[3 * (size_t)f + d] - est[3 * (size_t)c + d]) * fa[3 * (size_t)f + d] * sign;
            const double pv = h / 3.0;
            for (int d = 0; d < 3; ++d)
                cc[3 * (size_t)c + d] += pv * (0.75 * fc[3 * (size_t)f + d] + 0.25 * est[3 * (size_t)c + d]);
            cv[c] += pv;
        }
    }
    for (int32_t c = 0; c < m->n_cells; ++c)
        for (int d = 0; d < 3; ++d) cc[3 * (size_t)c + d] /= cv[c];
    free(est);
    free(nf);
}

int box_mesh_create(box_mesh *b, int nx, int ny, int nz, const double lo[3], const double hi[3],
                    const uint8_t kinds[6], double shear)
{
    memset(b, 0, sizeof *b);
    b->nx = nx;
    b->ny = ny;
    b->nz = nz;
    const size_t np = (size_t)(nx + 1) * (ny + 1) * (nz + 1), nc = (size_t)nx * ny * nz;
    const size_t ni = (size_t)(nx - 1) * ny * nz + (size_t)nx * (ny - 1) * nz + (size_t)nx * ny * (nz - 1);
    const size_t nb = 2 * ((size_t)ny * nz + (size_t)nx * nz + (size_t)nx * ny), nf = ni + nb;
    b->points = malloc(3 * np * sizeof(double));
    b->face_point_offsets = malloc((nf + 1) * sizeof(int32_t));
    b->face_points = malloc(4 * nf * sizeof(int32_t));
    b->owner = malloc(nf * sizeof(int32_t));
    b->neighbour = malloc((ni ? ni : 1) * sizeof(int32_t));
    b->boundary_face_kind = malloc(nb * sizeof(uint8_t));
    b->face_centres = malloc(3 * nf * sizeof(double));
    b->face_areas = malloc(3 * nf * sizeof(double));
    b->cell_centres = malloc(3 * nc * sizeof(double));
    b->cell_volumes = malloc(nc * sizeof(double));
    if (!b->points || !b->face_point_offsets || !b->face_points || !b->owner || !b->neighbour ||
        !b->boundary_face_kind || !b->face_centres || !b->face_areas || !b->cell_centres || !b->cell_volumes) {
        box_mesh_destroy(b);
        return -1;
    }
#define PT(i, j, k) ((int32_t)(((size_t)(k) * (ny + 1) + (j)) * (nx + 1) + (i)))
#define CL(i, j, k) ((int32_t)(((size_t)(k) * ny + (j)) * nx + (i)))
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) {
                double *p = b->points + 3 * (size_t)PT(i, j, k);
                p[0] = lo[0] + (hi[0] - lo[0]) * i / nx;
                p[1] = lo[1] + (hi[1] - lo[1]) * j / ny;
                p[2] = lo[2] + (hi[2] - lo[2]) * k / nz;
                p[0] += shear * (p[1] - lo[1]);
            }
    size_t f = 0;
    int32_t *fp = b->face_points;
    /* Face point order gives an area vector out of the owner (right-hand rule). */
#define FACE(a, bb, c, d, own)                                                                                        \
    do {                                                                                                           \
        b->face_point_offsets[f] = (int32_t)(4 * f);                                                               \
        fp[4 * f] = (a);                                                                                           \
        fp[4 * f + 1] = (bb);                                                                                      \
        fp[4 * f + 2] = (c);                                                                                       \
        fp[4 * f + 3] = (d);                                                                                       \
        b->owner[f] = (own);                                                                                       \
    } while (0)
    /* internal faces in owner order (upper-triangular, as OpenFOAM requires) */
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                if (i + 1 < nx) { /* +x face */
                    FACE(PT(i + 1, j, k), PT(i + 1, j + 1, k), PT(i + 1, j + 1, k + 1), PT(i + 1, j, k + 1), CL(i, j, k));
                    b->neighbour[f++] = CL(i + 1, j, k);
                }
                if (j + 1 < ny) { /* +y face */
                    FACE(PT(i, j + 1, k), PT(i, j + 1, k + 1), PT(i + 1, j + 1, k + 1), PT(i + 1, j + 1, k), CL(i, j, k));
                    b->neighbour[f++] = CL(i, j + 1, k);
                }
                if (k + 1 < nz) { /* +z face */
                    FACE(PT(i, j, k + 1), PT(i + 1, j, k + 1), PT(i + 1, j + 1, k + 1), PT(i, j + 1, k + 1), CL(i, j, k));
                    b->neighbour[f++] = CL(i, j, k + 1);
                }
            }
    /* boundary patches: xmin xmax ymin ymax zmin zmax */
    for (int patch = 0; patch < 6; ++patch) {
        b->patch_start[patch] = (int32_t)(f - ni);
        const size_t f0 = f;
        for (int k = 0; k < nz; ++k)
            for (int j = 0; j < ny; ++j)
                for (int i = 0; i < nx; ++i) {
                    switch (patch) {
                    case 0: if (i == 0) FACE(PT(0, j, k), PT(0, j, k + 1), PT(0, j + 1, k + 1), PT(0, j + 1, k), CL(i, j, k)); else continue; break;
                    case 1: if (i == nx - 1) FACE(PT(nx, j, k), PT(nx, j + 1, k), PT(nx, j + 1, k + 1), PT(nx, j, k + 1), CL(i, j, k)); else continue; break;
                    case 2: if (j == 0) FACE(PT(i, 0, k), PT(i + 1, 0, k), PT(i + 1, 0, k + 1), PT(i, 0, k + 1), CL(i, j, k)); else continue; break;
                    case 3: if (j == ny - 1) FACE(PT(i, ny, k), PT(i, ny, k + 1), PT(i + 1, ny, k + 1), PT(i + 1, ny, k), CL(i, j, k)); else continue; break;
                    case 4: if (k == 0) FACE(PT(i, j, 0), PT(i, j + 1, 0), PT(i + 1, j + 1, 0), PT(i + 1, j, 0), CL(i, j, k)); else continue; break;
                    default: if (k == nz - 1) FACE(PT(i, j, nz), PT(i + 1, j, nz), PT(i + 1, j + 1, nz), PT(i, j + 1, nz), CL(i, j, k)); else continue; break;
                    }
                    b->boundary_face_kind[f - ni] = kinds[patch];
                    ++f;
                }
        b->patch_size[patch] = (int32_t)(f - f0);
    }
    b->face_point_offsets[f] = (int32_t)(4 * f);
#undef FACE
#undef PT
#undef CL
    cdc_mesh *m = &b->mesh;
    m->n_points = (int32_t)np;
    m->n_cells = (int32_t)nc;
    m->n_faces = (int32_t)nf;
    m->n_internal_faces = (int32_t)ni;
    m->points = b->points;
    m->face_point_offsets = b->face_point_offsets;
    m->face_points = b->face_points;
    m->owner = b->owner;
    m->neighbour = b->neighbour;
    m->face_centres = b->face_centres;
    m->face_areas = b->face_areas;
    m->cell_centres = b->cell_centres;
    m->cell_volumes = b->cell_volumes;
    m->boundary_face_kind = b->boundary_face_kind;
    box_mesh_geometry(m, b->face_centres, b->face_areas, b->cell_centres, b->cell_volumes);
    return 0;
}

void box_mesh_destroy(box_mesh *b)
{
    free(b->points);
    free(b->face_point_offsets);
    free(b->face_points);
    free(b->owner);
    free(b->neighbour);
    free(b->boundary_face_kind);
    free(b->face_centres);
    free(b->face_areas);
    free(b->cell_centres);
    free(b->cell_volumes);
    memset(b, 0, sizeof *b);
}
