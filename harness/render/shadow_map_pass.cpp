#include "render/shadow_map_pass.hpp"

#include "gpu/rendering.hpp"

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
    begin_rendering(commands, depth_.width(), depth_.height(), {}, DepthTarget{depth_.view(), true});
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, layout, true);
    vkCmdEndRendering(commands);
    transition(commands, depth_, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL);
}

}  // namespace canopy
