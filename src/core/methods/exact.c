/*
 * exact -- the reference: w_c = |sphere ∩ cell| / |sphere| for box (axis-aligned hexahedral)
 * cells, computed by cdc_sphere_box_volume to ~1e-12. The part of a particle beyond the mesh
 * (through a wall) is renormalised away so volume is conserved, like every other method.
 */
#include "common.h"

static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    (void)prm;
    cdc_status st = cdc_cells_overlapping(ctx, p->x, p->host, p->ghost, p->r, &ctx->near_cells);
    if (st != CDC_OK) return st;
    const double vol = 4.0 / 3.0 * CDC_PI * p->r * p->r * p->r;
    for (size_t q = 0; q < ctx->near_cells.n; ++q) {
        const int32_t c = ctx->near_cells.v[q];
        if (!ctx->cell_is_box[c])
            return cdc_fail(ctx, CDC_ERR_UNSUPPORTED,
                            "exact: cell %d is not an axis-aligned box; the exact method needs a hexahedral "
                            "box mesh (use divided for general cells)", (int)c);
        const double *bb = ctx->cell_bbox + 6 * (size_t)c;
        const double v = cdc_sphere_box_volume(p->x, p->r, bb, bb + 3);
        if (v > 1e-14 * vol && cdc_kernel_add(out, c, v / vol))
            return cdc_fail(ctx, CDC_ERR_NOMEM, "exact: out of memory");
    }
    return CDC_OK;
}

const cdc_method cdc_method_exact = {"exact", 0, cdc_check_no_params, cdc_reach_radius, build};
