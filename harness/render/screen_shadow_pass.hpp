// Screen-space shadow buffers (ScreenShadowNeeds): a camera pass writing per-pixel shadow data
// and normals, then a chain of screen-space filters over the shadow data.
#pragma once

#include "core/technique.hpp"
#include "render/filter_chain.hpp"
#include "render/gpu_scene.hpp"

#include <memory>

namespace canopy {

class ScreenShadowPass {
public:
    static constexpr VkFormat kDataFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr VkFormat kNormalFormat = VK_FORMAT_R16G16B16A16_SFLOAT;

    ScreenShadowPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
                     const ScreenShadowNeeds& needs, VkPipelineLayout scene_layout, VkBuffer frame_uniforms,
                     VkImageView shadow_depth);
    void record_render(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout scene_layout,
                       VkDescriptorSet frame) const;
    size_t filter_count() const { return filters_ ? filters_->size() : 0; }
    const std::string& filter_name(size_t index) const { return filters_->name(index); }
    void record_filter(VkCommandBuffer commands, size_t index) const { filters_->record(commands, index); }
    VkImageView result() const { return filters_ ? filters_->result() : data_.view(); }
    const Texture& result_texture() const { return filters_ ? filters_->result_texture() : data_; }

private:
    Texture data_;
    Texture normals_;
    Texture depth_;
    std::unique_ptr<GraphicsPipeline> pipeline_;
    std::unique_ptr<FilterChain> filters_;
};

}  // namespace canopy
