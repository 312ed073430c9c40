// A colour shadow map of depth statistics (MomentMapNeeds): rendered from the shadow light,
// then prefiltered by separable compute passes that ping-pong between two images.
#pragma once

#include "core/technique.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/resources.hpp"
#include "render/filter_chain.hpp"
#include "render/gpu_scene.hpp"

#include <memory>
#include <vector>

namespace canopy {

VkFormat vk_format(MomentFormat format);

class MomentMapPass {
public:
    MomentMapPass(const GpuContext& gpu, MemoryLedger& ledger, const MomentMapNeeds& needs, VkPipelineLayout scene_layout);
    MomentMapPass(const MomentMapPass&) = delete;
    MomentMapPass& operator=(const MomentMapPass&) = delete;

    // Renders the statistics; leaves the map in SHADER_READ_ONLY_OPTIMAL.
    void record_render(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout scene_layout,
                       VkDescriptorSet frame) const;
    // Prefilter pass `index`; leaves its output in SHADER_READ_ONLY_OPTIMAL.
    void record_filter(VkCommandBuffer commands, size_t index) const;
    size_t filter_count() const { return filters_ ? filters_->size() : 0; }
    const std::string& filter_name(size_t index) const { return filters_->name(index); }
    // The map the lit pass samples: the last filter's output, or the render without filters.
    VkImageView result() const;

private:
    MomentMapNeeds needs_;
    Texture target_;  // the rendered statistics; later prefilter passes write back into it
    Texture depth_;   // z-buffer of the render, transient
    std::unique_ptr<GraphicsPipeline> render_pipeline_;
    std::unique_ptr<FilterChain> filters_;
};

}  // namespace canopy
