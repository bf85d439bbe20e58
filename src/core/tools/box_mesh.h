/*
 * box_mesh.h -- a structured hexahedral mesh in OpenFOAM's face-addressed form, for the tests,
 * the particleDistribution tutorial and the benchmarks (what blockMesh would give for one block).
 * Not part of the core library: the core takes any mesh through cdc_mesh.
 */
#ifndef CDC_BOX_MESH_H
#define CDC_BOX_MESH_H

#include "../coarse_dem.h"

typedef struct box_mesh {
    cdc_mesh mesh;  /* view handed to the core; arrays below own the data */
    int nx, ny, nz;
    double *points, *face_centres, *face_areas, *cell_centres, *cell_volumes;
    int32_t *face_point_offsets, *face_points, *owner, *neighbour;
    uint8_t *boundary_face_kind;
    int32_t patch_start[6], patch_size[6]; /* xmin xmax ymin ymax zmin zmax, as boundary face offsets */
} box_mesh;

/* nx*ny*nz cells on [lo, hi]; kinds[6] = cdc_face_kind of the xmin, xmax, ymin, ymax, zmin, zmax
 * patches. shear != 0 maps x -> x + shear * (y - lo[1]) so cells become parallelepipeds (a skewed,
 * non-box test mesh). Returns 0 on success. */
int box_mesh_create(box_mesh *b, int nx, int ny, int nz, const double lo[3], const double hi[3],
                    const uint8_t kinds[6], double shear);
void box_mesh_destroy(box_mesh *b);

/* Face centres/areas (triangles about the face's mean point) and cell centres/volumes (pyramids
 * about the cell's mean face centre), as OpenFOAM computes them; for meshes built by hand. */
void box_mesh_geometry(cdc_mesh *m, double *face_centres, double *face_areas, double *cell_centres,
                       double *cell_volumes);

/* Index of cell (i,j,k). */
static inline int32_t box_mesh_cell(const box_mesh *b, int i, int j, int k)
{
    return (int32_t)(((size_t)k * b->ny + j) * b->nx + i);
}
#endif
