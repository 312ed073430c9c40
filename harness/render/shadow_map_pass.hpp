// Renders the shadow casters' linear light-space depth into a depth texture.
#pragma once

#include "core/technique.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/resources.hpp"
#include "render/gpu_scene.hpp"

#include <memory>

namespace canopy {

VkFormat vk_format(DepthFormat format);

class ShadowMapPass {
public:
    ShadowMapPass(const GpuContext& gpu, MemoryLedger& ledger, const ShadowMapNeeds& needs, VkPipelineLayout layout);
    // Leaves the map in DEPTH_READ_ONLY_OPTIMAL for the passes that sample it.
    void record(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout layout, VkDescriptorSet frame) const;
    const Texture& depth() const { return depth_; }

private:
    Texture depth_;
    std::unique_ptr<GraphicsPipeline> pipeline_;
};

}  // namespace canopy
