/* common.h -- the small parts methods share: "no parameters to check" and "reaches its radius". */
#ifndef CDC_METHODS_COMMON_H
#define CDC_METHODS_COMMON_H
#include "../internal.h"

static inline cdc_status cdc_check_no_params(cdc_context *ctx, const cdc_kernel_params *prm)
{
    (void)ctx;
    (void)prm;
    return CDC_OK;
}

static inline double cdc_reach_radius(const cdc_kernel_params *prm, double r)
{
    (void)prm;
    return r;
}
#endif
