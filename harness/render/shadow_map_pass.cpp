#include "render/shadow_map_pass.hpp"

#include "shaders/shadow_depth_frag.h"
#include "shaders/shadow_depth_vert.h"

namespace canopy {

VkFormat vk_format(DepthFormat format) {
    return format == DepthFormat::d16 ? VK_FORMAT_D16_UNORM : VK_FORMAT_D32_SFLOAT;
}

ShadowMapPass::ShadowMapPass(const GpuContext& gpu, MemoryLedger& ledger, const ShadowMapNeeds& needs,
                             VkPipelineLayout layout)
    : depth_(gpu, ledger, "technique", needs.resolution, needs.resolution, vk_format(needs.format),
             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT, VK_IMAGE_ASPECT_DEPTH_BIT) {
    GraphicsPipelineDesc desc;
    desc.vertex_spirv = shadow_depth_vert;
    desc.fragment_spirv = shadow_depth_frag;
    desc.layout = layout;
    desc.depth_format = depth_.format();
    pipeline_ = std::make_unique<GraphicsPipeline>(gpu, desc);
}

void ShadowMapPass::record(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout layout,
                           VkDescriptorSet frame) const {
    transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    VkRenderingAttachmentInfo depth_attachment{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    depth_attachment.imageView = depth_.view();
    depth_attachment.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
    depth_attachment.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    depth_attachment.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    depth_attachment.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, {depth_.width(), depth_.height()}};
    rendering.layerCount = 1;
    rendering.pDepthAttachment = &depth_attachment;
    vkCmdBeginRendering(commands, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(depth_.width()), float(depth_.height()), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, {depth_.width(), depth_.height()}};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, layout, true);
    vkCmdEndRendering(commands);
    transition(commands, depth_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL);
}

}  // namespace canopy
