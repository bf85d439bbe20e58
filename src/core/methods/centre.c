/*
 * centre -- particle centroid method (PCM): the whole particle volume goes to its host cell.
 * The classic CFDEM "centre" model; spikes once particles are as large as the cells.
 */
#include "common.h"

static double reach(const cdc_kernel_params *prm, double r)
{
    (void)prm;
    (void)r;
    return 0.0;
}

static cdc_status build(cdc_context *ctx, const cdc_kernel_params *prm, const cdc_particle_in *p,
                        cdc_kernel_builder *out)
{
    (void)prm;
    if (p->ghost) return CDC_OK; /* the host cell is on the owner's rank */
    if (cdc_kernel_add(out, p->host, 1.0)) return cdc_fail(ctx, CDC_ERR_NOMEM, "centre: out of memory");
    return CDC_OK;
}

const cdc_method cdc_method_centre = {"centre", 0, cdc_check_no_params, reach, build};
