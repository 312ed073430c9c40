#include "render/screen_shadow_pass.hpp"

#include "gpu/rendering.hpp"

#include "shaders/scene_vert.h"

#include <array>

namespace canopy {

ScreenShadowPass::ScreenShadowPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
                                   const ScreenShadowNeeds& needs, VkPipelineLayout scene_layout,
                                   VkBuffer frame_uniforms, VkImageView shadow_depth)
    : data_(gpu, ledger, "technique", width, height, kDataFormat,
            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
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
    // Background: fully lit, no blur, infinitely far (so filters never mix it with surfaces).
    const std::array<ColorTarget, 2> colors{{{data_.view(), {{1.0f, 0.0f, 0.0f, 1e30f}}},
                                             {normals_.view(), {{0.0f, 0.0f, 0.0f, 0.0f}}}}};
    begin_rendering(commands, data_.width(), data_.height(), colors, DepthTarget{depth_.view(), false});
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, scene_layout, false);
    vkCmdEndRendering(commands);
    transition(commands, data_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    transition(commands, normals_, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

}  // namespace canopy
