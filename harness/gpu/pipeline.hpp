// Graphics pipelines for dynamic rendering over canopy's one vertex layout (position, normal).
#pragma once

#include "gpu/context.hpp"

#include <cstdint>
#include <span>
#include <vector>

namespace canopy {

struct GraphicsPipelineDesc {
    std::span<const uint32_t> vertex_spirv;
    std::span<const uint32_t> fragment_spirv;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    std::vector<VkFormat> color_formats;          // empty for depth-only passes
    VkFormat depth_format = VK_FORMAT_UNDEFINED;
    VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;      // scenes hold open surfaces (planes)
};

// Owns one VkPipeline.
class GraphicsPipeline {
public:
    GraphicsPipeline(const GpuContext& gpu, const GraphicsPipelineDesc& desc);
    ~GraphicsPipeline();
    GraphicsPipeline(const GraphicsPipeline&) = delete;
    GraphicsPipeline& operator=(const GraphicsPipeline&) = delete;
    VkPipeline handle() const { return pipeline_; }

private:
    const GpuContext& gpu_;
    VkPipeline pipeline_ = VK_NULL_HANDLE;
};

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
