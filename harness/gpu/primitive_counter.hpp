// The triangles a frame submits (input assembly) and that come out of clipping, which the
// rasteriser then sees: a Vulkan pipeline-statistics query around a whole phase. Lemme's Table 7.1
// quotes the first for the blades and the second for the volume (its cuboids' faces a ray enters
// by are drawn but clipped away). Counting is for untimed frames: it may cost time on some devices.
#pragma once

#include "gpu/context.hpp"

#include <cstdint>

namespace canopy {

struct PrimitiveCounts {
    uint64_t submitted = 0;   // VK_QUERY_PIPELINE_STATISTIC_INPUT_ASSEMBLY_PRIMITIVES_BIT
    uint64_t rasterised = 0;  // VK_QUERY_PIPELINE_STATISTIC_CLIPPING_PRIMITIVES_BIT
};

class PrimitiveCounter {
public:
    explicit PrimitiveCounter(const GpuContext& gpu);  // the device must have pipeline_statistics()
    ~PrimitiveCounter();
    PrimitiveCounter(const PrimitiveCounter&) = delete;
    PrimitiveCounter& operator=(const PrimitiveCounter&) = delete;

    // Record both outside any render pass, `begin` before the first draw and `end` after the last.
    void begin(VkCommandBuffer commands);
    void end(VkCommandBuffer commands);
    PrimitiveCounts read() const;  // after the submission completed

private:
    const GpuContext& gpu_;
    VkQueryPool pool_ = VK_NULL_HANDLE;
};

}  // namespace canopy
