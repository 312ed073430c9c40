#include "graph/pipeline_cache.hpp"

#include "core/error.hpp"
#include "gpu/pipeline.hpp"

#include "scene/geometry.hpp"
#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <array>
#include <cstddef>

namespace canopy {

VertexLayout VertexLayout::scene() {
    VertexLayout layout;
    layout.bindings.push_back({uint32_t(sizeof(Vertex)), false});
    layout.attributes.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, position))});
    layout.attributes.push_back({1, 0, VK_FORMAT_R32G32B32_SFLOAT, uint32_t(offsetof(Vertex, normal))});
    return layout;
}

VertexLayout& VertexLayout::population_copies() {
    const uint32_t stride = uint32_t(sizeof(PopulationInstance));
    const uint32_t binding = uint32_t(bindings.size());
    instance_mat4(2, stride, uint32_t(offsetof(PopulationInstance, model)));
    for (uint32_t c = 0; c < 3; ++c)
        attributes.push_back({6 + c, binding, VK_FORMAT_R32G32B32A32_SFLOAT,
                              uint32_t(offsetof(PopulationInstance, normal_matrix)) + 16 * c});
    attributes.push_back({9, binding, VK_FORMAT_R32G32B32A32_SFLOAT, uint32_t(offsetof(PopulationInstance, data))});
    return *this;
}

VertexLayout VertexLayout::population() {
    VertexLayout layout = scene();
    layout.population_copies();
    layout.bindings.push_back({uint32_t(sizeof(PopulationVertexData)), false});
    for (uint32_t v = 0; v < 2; ++v)
        layout.attributes.push_back({10 + v, 2, VK_FORMAT_R32G32B32A32_SFLOAT,
                                     uint32_t(offsetof(PopulationVertexData, data)) + 16 * v});
    return layout;
}

VertexLayout& VertexLayout::instance_mat4(uint32_t first_location, uint32_t stride, uint32_t offset) {
    const uint32_t binding = uint32_t(bindings.size());
    bindings.push_back({stride, true});
    for (uint32_t c = 0; c < 4; ++c)
        attributes.push_back({first_location + c, binding, VK_FORMAT_R32G32B32A32_SFLOAT, offset + 16 * c});
    return *this;
}

std::string VertexLayout::describe() const {
    std::string out;
    for (const Binding& b : bindings) out += fmt::format("b{}{} ", b.stride, b.per_instance ? "i" : "v");
    for (const Attribute& a : attributes) out += fmt::format("a{}:{}:{}:{} ", a.location, a.binding, int(a.format), a.offset);
    return out;
}

namespace {

std::string spirv_key(std::span<const uint32_t> spirv) {
    return fmt::format("{}:{}", static_cast<const void*>(spirv.data()), spirv.size());
}

VkPipelineColorBlendAttachmentState blend_state(Blend blend) {
    VkPipelineColorBlendAttachmentState b{};
    b.colorWriteMask = 0xF;
    if (blend == Blend::none) return b;
    b.blendEnable = VK_TRUE;
    b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
    if (blend == Blend::alpha) {
        b.srcColorBlendFactor = VK_BLEND_FACTOR_SRC_ALPHA;
        b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
        b.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA;
    } else {
        b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
    }
    return b;
}

}  // namespace

PipelineCache::~PipelineCache() {
    for (auto& [key, pipeline] : pipelines_) vkDestroyPipeline(gpu_.device(), pipeline, nullptr);
}

VkPipeline PipelineCache::raster(const RasterState& s, const AttachmentFormats& targets, VkPipelineLayout layout) {
    std::string key = fmt::format("raster {} {} {} {} {} {} {} {} {} {} {} {} {} {} {}|", spirv_key(s.vertex_spirv),
                                  spirv_key(s.fragment_spirv), s.vertices.describe(), int(s.topology), s.cull,
                                  s.depth_test, s.depth_write, int(s.depth_compare), int(s.blend), s.alpha_to_coverage,
                                  s.sample_shading, int(targets.depth), targets.samples, static_cast<const void*>(layout),
                                  targets.colors.size());
    for (VkFormat f : targets.colors) key += fmt::format("{},", int(f));
    if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
    if (s.sample_shading && !gpu_.sample_rate_shading())
        throw GpuError(fmt::format("device '{}' cannot run a fragment shader per sample (no sampleRateShading feature); "
                                   "turn the technique's per-sample option off (grass.lod: middle_per_sample = false)",
                                   gpu_.info().name));

    VkDevice device = gpu_.device();
    VkShaderModule vertex = create_shader_module(device, s.vertex_spirv);
    VkShaderModule fragment = s.fragment_spirv.empty() ? VK_NULL_HANDLE : create_shader_module(device, s.fragment_spirv);
    std::vector<VkPipelineShaderStageCreateInfo> stages;
    stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_VERTEX_BIT, vertex,
                      "main", nullptr});
    if (fragment)
        stages.push_back({VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0, VK_SHADER_STAGE_FRAGMENT_BIT,
                          fragment, "main", nullptr});
    std::vector<VkVertexInputBindingDescription> bindings;
    for (size_t i = 0; i < s.vertices.bindings.size(); ++i)
        bindings.push_back({uint32_t(i), s.vertices.bindings[i].stride,
                            s.vertices.bindings[i].per_instance ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX});
    std::vector<VkVertexInputAttributeDescription> attributes;
    for (const VertexLayout::Attribute& a : s.vertices.attributes)
        attributes.push_back({a.location, a.binding, a.format, a.offset});
    VkPipelineVertexInputStateCreateInfo vertex_input{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vertex_input.vertexBindingDescriptionCount = uint32_t(bindings.size());
    vertex_input.pVertexBindingDescriptions = bindings.data();
    vertex_input.vertexAttributeDescriptionCount = uint32_t(attributes.size());
    vertex_input.pVertexAttributeDescriptions = attributes.data();
    VkPipelineInputAssemblyStateCreateInfo assembly{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    assembly.topology = s.topology;
    VkPipelineViewportStateCreateInfo viewport{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo raster{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = s.cull;
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo multisample{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    multisample.rasterizationSamples = VkSampleCountFlagBits(targets.samples);
    multisample.alphaToCoverageEnable = s.alpha_to_coverage ? VK_TRUE : VK_FALSE;
    multisample.sampleShadingEnable = s.sample_shading && targets.samples > 1 ? VK_TRUE : VK_FALSE;
    multisample.minSampleShading = 1.0f;
    // The covered samples store alpha 1: the resolved alpha is then the pixel's covered share
    // (raster_state.hpp). Without the feature it is alpha times that share.
    multisample.alphaToOneEnable = s.alpha_to_coverage && gpu_.alpha_to_one() ? VK_TRUE : VK_FALSE;
    VkPipelineDepthStencilStateCreateInfo depth{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    depth.depthTestEnable = s.depth_test && targets.depth != VK_FORMAT_UNDEFINED;
    depth.depthWriteEnable = s.depth_write && targets.depth != VK_FORMAT_UNDEFINED;
    depth.depthCompareOp = s.depth_compare;
    std::vector<VkPipelineColorBlendAttachmentState> blend_attachments(targets.colors.size(), blend_state(s.blend));
    VkPipelineColorBlendStateCreateInfo blend{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    blend.attachmentCount = uint32_t(blend_attachments.size());
    blend.pAttachments = blend_attachments.data();
    std::array<VkDynamicState, 2> dynamic_states{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dynamic.dynamicStateCount = uint32_t(dynamic_states.size());
    dynamic.pDynamicStates = dynamic_states.data();
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(targets.colors.size());
    rendering.pColorAttachmentFormats = targets.colors.data();
    rendering.depthAttachmentFormat = targets.depth;
    VkGraphicsPipelineCreateInfo info{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    info.pNext = &rendering;
    info.stageCount = uint32_t(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertex_input;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &blend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VkResult result = vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline);
    vkDestroyShaderModule(device, vertex, nullptr);
    if (fragment) vkDestroyShaderModule(device, fragment, nullptr);
    vk_check(result, "vkCreateGraphicsPipelines");
    pipelines_.emplace(key, pipeline);
    return pipeline;
}

VkPipeline PipelineCache::compute(std::span<const uint32_t> spirv, VkPipelineLayout layout) {
    const std::string key = fmt::format("compute {} {}", spirv_key(spirv), static_cast<const void*>(layout));
    if (auto it = pipelines_.find(key); it != pipelines_.end()) return it->second;
    const VkPipeline pipeline = create_compute_pipeline(gpu_.device(), spirv, layout);
    pipelines_.emplace(key, pipeline);
    return pipeline;
}

}  // namespace canopy
