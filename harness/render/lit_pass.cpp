#include "render/lit_pass.hpp"

#include "shaders/scene_vert.h"

namespace canopy {

LitPass::LitPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
                 std::span<const uint32_t> fragment_spirv, VkPipelineLayout layout)
    : color_(gpu, ledger, "targets", width, height, kColorFormat,
             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT),
      depth_(gpu, ledger, "targets", width, height, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
             VK_IMAGE_ASPECT_DEPTH_BIT) {
    GraphicsPipelineDesc desc;
    desc.vertex_spirv = scene_vert;
    desc.fragment_spirv = fragment_spirv;
    desc.layout = layout;
    desc.color_formats = {kColorFormat};
    desc.depth_format = kDepthFormat;
    pipeline_ = std::make_unique<GraphicsPipeline>(gpu, desc);
}

void LitPass::record(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout layout, VkDescriptorSet frame,
                     const glm::vec3& background) const {
    transition(commands, color_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    color.imageView = color_.view();
    color.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    color.clearValue.color = {{background.r, background.g, background.b, 1.0f}};
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth.imageView = depth_.view();
    depth.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    depth.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {color_.width(), color_.height()}};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = 1;
    rendering.pColorAttachments = &color;
    rendering.pDepthAttachment = &depth;
    vkCmdBeginRendering(commands, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(color_.width()), float(color_.height()), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {color_.width(), color_.height()}};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, layout, false);
    vkCmdEndRendering(commands);
    transition(commands, color_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

}  // namespace canopy
