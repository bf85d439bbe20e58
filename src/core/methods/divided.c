/*
 * divided -- divided particle volume method (DPVM) with 29 marker points
 * (Wu et al.; Zhang et al., Phys. Fluids 35, 113330 (2023), §II.A, eqs. 3-4, Fig. 1).
 *
 * The sphere is cut into 29 parts of equal volume: a core sphere of radius r1 = R (1/29)^(1/3)
 * and two shells r1..r2 and r2..R, r2 = R (15/29)^(1/3), each shell cut into 14 parts. Each part is
 * represented by a marker at its centroid radius along one of 14 directions (6 axes + 8 cube
 * diagonals). The weight of a cell is the share of markers it holds. Markers outside the mesh
 * (a particle through a wall) are dropped and the rest renormalised, so volume is conserved.
 */
#include "common.h"


static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    (void)prm;
    static const double s3 = 0.57735026918962576451; /* 1/sqrt(3) */
    static const double dirs[14][3] = {{1, 0, 0},   {-1, 0, 0},   {0, 1, 0},   {0, -1, 0},  {0, 0, 1},
                                       {0, 0, -1},  {s3, s3, s3}, {s3, s3, -s3}, {s3, -s3, s3},
                                       {s3, -s3, -s3}, {-s3, s3, s3}, {-s3, s3, -s3}, {-s3, -s3, s3},
                                       {-s3, -s3, -s3}};
    /* Marker radii, in particle radii: the centroid radius of a shell a..b, int r^3 dr / int r^2 dr =
     * 3/4 (b^4 - a^4) / (b^3 - a^3), for the shells (1/29)^(1/3)..(15/29)^(1/3) and (15/29)^(1/3)..1,
     * evaluated to 40 digits once (eq. 3 of the paper prints this with the factors garbled; this is
     * the centroid it defines). */
    const double radii[2] = {0.62760653948115238019 * p->r, 0.90852807133647256873 * p->r};

    /* the central marker is in the host cell, which is on the owner's rank for a ghost */
    if (!p->ghost && cdc_kernel_add(out, p->host, 1.0)) return cdc_fail(ctx, CDC_ERR_NOMEM, "divided: out of memory");
    for (int layer = 0; layer < 2; ++layer)
        for (int k = 0; k < 14; ++k) {
            const double m[3] = {p->x[0] + radii[layer] * dirs[k][0], p->x[1] + radii[layer] * dirs[k][1],
                                 p->x[2] + radii[layer] * dirs[k][2]};
            int32_t c;
            cdc_status st = cdc_locate_point(ctx, m, p->host, &c);
            if (st != CDC_OK) return st;
            if (c < 0) continue; /* marker outside the mesh: dropped, the rest renormalised */
            if (cdc_kernel_add(out, c, 1.0)) return cdc_fail(ctx, CDC_ERR_NOMEM, "divided: out of memory");
        }
    return CDC_OK;
}

const cdc_method cdc_method_divided = {"divided", 0, cdc_check_no_params, cdc_reach_radius, build};
