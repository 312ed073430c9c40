// Compute pipelines outside frame graphs (frame-graph pipelines: graph/pipeline_cache.hpp), and
// the shader modules every pipeline is made from.
#pragma once

#include "gpu/context.hpp"

#include <cstdint>
#include <span>

namespace canopy {

// A shader module for `spirv`; the caller destroys it once its pipeline exists.
VkShaderModule create_shader_module(VkDevice device, std::span<const uint32_t> spirv);
// A compute pipeline running `spirv` with `layout`; the caller owns it.
VkPipeline create_compute_pipeline(VkDevice device, std::span<const uint32_t> spirv, VkPipelineLayout layout);

// Owns one compute VkPipeline.
class ComputePipeline {
public:
    ComputePipeline(const GpuContext& gpu, std::span<const uint32_t> spirv, VkPipelineLayout layout);
    ~ComputePipeline();
    ComputePipeline(const ComputePipeline&) = delete;
    ComputePipeline& operator=(const ComputePipeline&) = delete;
    VkPipeline handle() const { return pipeline_; }

private:
    const GpuContext& gpu_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

}  // namespace canopy
