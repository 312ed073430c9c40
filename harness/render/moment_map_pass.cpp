#include "render/moment_map_pass.hpp"

#include "gpu/rendering.hpp"

#include "shaders/shadow_depth_vert.h"


namespace canopy {

VkFormat vk_format(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return VK_FORMAT_R16_SFLOAT;
        case MomentFormat::r32f: return VK_FORMAT_R32_SFLOAT;
        case MomentFormat::rg16f: return VK_FORMAT_R16G16_SFLOAT;
        case MomentFormat::rg32f: return VK_FORMAT_R32G32_SFLOAT;
        case MomentFormat::rgba16f: return VK_FORMAT_R16G16B16A16_SFLOAT;
        case MomentFormat::rgba32f: return VK_FORMAT_R32G32B32A32_SFLOAT;
        case MomentFormat::rgba16unorm: return VK_FORMAT_R16G16B16A16_UNORM;
    }
    return VK_FORMAT_UNDEFINED;
}

MomentMapPass::MomentMapPass(const GpuContext& gpu, MemoryLedger& ledger, const MomentMapNeeds& needs,
                             VkPipelineLayout scene_layout)
    : needs_(needs) {
    const VkFormat format = vk_format(needs.format);
    const uint32_t size = needs.resolution;
    const bool filtered = !needs.prefilter.empty();
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT |
                                    (filtered ? VK_IMAGE_USAGE_STORAGE_BIT : 0);
    target_ = Texture(gpu, ledger, "technique", size, size, format, usage, VK_IMAGE_ASPECT_COLOR_BIT);
    depth_ = Texture(gpu, ledger, "technique", size, size, VK_FORMAT_D32_SFLOAT,
                     VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT);

    GraphicsPipelineDesc desc;
    desc.vertex_spirv = shadow_depth_vert;
    desc.fragment_spirv = needs.fragment_spirv;
    desc.layout = scene_layout;
    desc.color_formats = {format};
    desc.depth_format = VK_FORMAT_D32_SFLOAT;
    render_pipeline_ = std::make_unique<GraphicsPipeline>(gpu, desc);
    if (filtered)
        filters_ = std::make_unique<FilterChain>(gpu, ledger, "technique", target_.view(),
                                                 VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, &target_, size, size, format,
                                                 needs.prefilter);
}

void MomentMapPass::record_render(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout scene_layout,
                                  VkDescriptorSet frame) const {
    const Texture& target = target_;
    transition(commands, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    transition(commands, depth_, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
    ColorTarget color{target.view(), {}};
    for (int c = 0; c < 4; ++c) color.clear.float32[c] = needs_.clear_value[size_t(c)];
    begin_rendering(commands, target.width(), target.height(), {&color, 1}, DepthTarget{depth_.view(), false});
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, render_pipeline_->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, scene_layout, 0, 1, &frame, 0, nullptr);
    scene.draw(commands, scene_layout, true);
    vkCmdEndRendering(commands);
    transition(commands, target, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

void MomentMapPass::record_filter(VkCommandBuffer commands, size_t index) const { filters_->record(commands, index); }

VkImageView MomentMapPass::result() const { return filters_ ? filters_->result() : target_.view(); }

}  // namespace canopy
