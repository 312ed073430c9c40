#include "render/lit_pass.hpp"

#include "gpu/rendering.hpp"
#include "lit_pass_output.h"

#include "shaders/scene_vert.h"

namespace canopy {

LitPass::LitPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
                 std::span<const uint32_t> fragment_spirv, VkPipelineLayout layout)
    : color_(gpu, ledger, "targets", width, height, kColorFormat,
             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_COLOR_BIT),
      depth_(gpu, ledger, "targets", width, height, kDepthFormat,
             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_IMAGE_ASPECT_DEPTH_BIT) {
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
    const ColorTarget color{color_.view(), {{background.r, background.g, background.b, shader::VISIBILITY_NOT_LIT}}};
    // Depth is stored: the technique-isolated error reads where each pixel centre hit.
    begin_rendering(commands, color_.width(), color_.height(), {&color, 1}, DepthTarget{depth_.view(), true});
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, layout, false);
    vkCmdEndRendering(commands);
    transition(commands, color_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
}

}  // namespace canopy
