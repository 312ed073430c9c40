// The parameters every prefiltered (moment-map) technique declares first, as entries of its
// params header's list (harness/shaders/param_block.h); all three shape the plan only
// (moment_map_needs): map size, channel precision and the separable prefilter's width.
#ifndef CANOPY_PREFILTER_PARAM_LIST_H
#define CANOPY_PREFILTER_PARAM_LIST_H

#define PREFILTER_RESOLUTION_PARAM(PLAN) \
    PLAN(integer, resolution, (1024, 16, 8192), "moment-map width and height in texels")
#define PREFILTER_FILTER_PARAM(PLAN)                   \
    PLAN(integer, filter, (5, 1, 63), "prefilter width in texels: separable (width x width) filter, 1 = none")
#define PREFILTER_PARAMS(PLAN)                                                                               \
    PREFILTER_RESOLUTION_PARAM(PLAN)                                                                         \
    PLAN(choice, precision, ("fp32", {"fp32", "fp16"}), "bits per moment channel: 32 or 16-bit float")       \
    PREFILTER_FILTER_PARAM(PLAN)

#endif
