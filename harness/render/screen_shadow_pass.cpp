#include "render/screen_shadow_pass.hpp"

#include "shaders/scene_vert.h"

#include <array>

namespace canopy {

ScreenShadowPass::ScreenShadowPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
                                   const ScreenShadowNeeds& needs, VkPipelineLayout scene_layout,
                                   VkBuffer frame_uniforms, VkImageView shadow_depth)
    : data_(gpu, ledger, "technique", width, height, kDataFormat,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT,
            VK_IMAGE_ASPECT_COLOR_BIT),
      normals_(gpu, ledger, "technique", width, height, kNormalFormat,
               VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_COLOR_BIT),
      depth_(gpu, ledger, "technique", width, height, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
             VK_IMAGE_ASPECT_DEPTH_BIT) {
    GraphicsPipelineDesc desc;
    desc.vertex_spirv = scene_vert;
    desc.fragment_spirv = needs.fragment_spirv;
    desc.layout = scene_layout;
    desc.color_formats = {kDataFormat, kNormalFormat};
    desc.depth_format = VK_FORMAT_D32_SFLOAT;
    pipeline_ = std::make_unique<GraphicsPipeline>(gpu, desc);
    if (!needs.filters.empty())
        filters_ = std::make_unique<FilterChain>(gpu, ledger, "technique", data_.view(),
                                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, &data_, width, height,
                                                 kDataFormat, needs.filters,
                                                 FilterExtras{frame_uniforms, shadow_depth, normals_.view()});
}

void ScreenShadowPass::record_render(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout scene_layout,
                                     VkDescriptorSet frame) const {
    transition(commands, data_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    transition(commands, normals_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    std::array<VkRenderingAttachmentInfo, 2> colors{};
    const std::array<const Texture*, 2> targets{&data_, &normals_};
    for (size_t i = 0; i < 2; ++i) {
        colors[i] = {VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        colors[i].imageView = targets[i]->view();
        colors[i].imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        colors[i].loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        colors[i].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    }
    // Background: fully lit, no blur, infinitely far (so filters never mix it with surfaces).
    colors[0].clearValue.color = {{1.0f, 0.0f, 0.0f, 1e30f}};
    colors[1].clearValue.color = {{0.0f, 0.0f, 0.0f, 0.0f}};
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = depth_.view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {data_.width(), data_.height()}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 2;
    rendering.pColorAttachments = colors.data();
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(commands, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(data_.width()), float(data_.height()), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {data_.width(), data_.height()}};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, scene_layout, false);
    vkCmdEndRendering(commands);
    transition(commands, data_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    transition(commands, normals_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

}  // namespace canopy
