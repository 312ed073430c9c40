// Graphics and compute pipelines, created once per distinct state and pipeline layout and kept for
// the renderer's lifetime (a frame recorded every frame must not create pipelines).
#pragma once

#include "gpu/context.hpp"
#include "graph/raster_state.hpp"

#include <map>
#include <span>
#include <string>
#include <vector>

namespace canopy {

// What a raster pass's attachments fix in its pipelines.
struct AttachmentFormats {
    std::vector<VkFormat> colors;
    VkFormat depth = VK_FORMAT_UNDEFINED;
    uint32_t samples = 1;
};

class PipelineCache {
public:
    explicit PipelineCache(const GpuContext& gpu) : gpu_(gpu) {}
    ~PipelineCache();
    PipelineCache(const PipelineCache&) = delete;
    PipelineCache& operator=(const PipelineCache&) = delete;

    VkPipeline raster(const RasterState& state, const AttachmentFormats& targets, VkPipelineLayout layout);
    VkPipeline compute(std::span<const uint32_t> spirv, VkPipelineLayout layout);
    size_t size() const { return pipelines_.size(); }

private:
    const GpuContext& gpu_;
    std::map<std::string, VkPipeline> pipelines_;
};

}  // namespace canopy
