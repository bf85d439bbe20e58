/* muller_bed.h -- the Mueller tutorial's mesh (8 x 36 x 100 cells on 10 x 44 x 120 mm, every boundary
 * a mirror wall) and its 9240 spheres of d = 1.2 mm placed at random in the lower 40 mm: the scene of
 * the kernel benchmarks kernelReuse and wallMirror. */
#ifndef BENCH_MULLER_BED_H
#define BENCH_MULLER_BED_H
#include "../src/core/tools/box_mesh.h"

#include <stdlib.h>

#define MULLER_N_PARTICLES 9240
#define MULLER_RADIUS 0.6e-3
static const double muller_lo[3] = {0.0, 0.0, 0.0}, muller_hi[3] = {0.010, 0.044, 0.120};

static double muller_uniform(void) { return (rand() + 0.5) / ((double)RAND_MAX + 1.0); }

/* the mesh; 0 when made */
static int muller_mesh(box_mesh *b)
{
    const uint8_t walls[6] = {CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL, CDC_FACE_WALL};
    return box_mesh_create(b, 8, 36, 100, muller_lo, muller_hi, walls, 0.0);
}

/* particle i's radius and a random position clear of the walls, below 40 mm (rand(): seed it first) */
static void muller_place(double *x, double *r, int i)
{
    r[i] = MULLER_RADIUS;
    x[3 * i] = MULLER_RADIUS + muller_uniform() * (muller_hi[0] - 2 * MULLER_RADIUS);
    x[3 * i + 1] = MULLER_RADIUS + muller_uniform() * (muller_hi[1] - 2 * MULLER_RADIUS);
    x[3 * i + 2] = MULLER_RADIUS + muller_uniform() * 0.040;
}
#endif
