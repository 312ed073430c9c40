// The camera pass: scene geometry shaded by canopy's one shading model, with visibility from
// the technique's fragment shader. Owns the colour (RGBA32F, linear; A = the technique's
// visibility, lit_pass_output.h) and depth targets; both are kept after the pass for readback.
#pragma once

#include "gpu/pipeline.hpp"
#include "gpu/resources.hpp"
#include "render/gpu_scene.hpp"

#include <memory>
#include <span>

namespace canopy {

class LitPass {
public:
    static constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
    static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

    LitPass(const GpuContext& gpu, MemoryLedger& ledger, uint32_t width, uint32_t height,
            std::span<const uint32_t> fragment_spirv, VkPipelineLayout layout);
    // Leaves the colour target in TRANSFER_SRC_OPTIMAL and the depth target in
    // DEPTH_ATTACHMENT_OPTIMAL, both stored, for readback.
    void record(VkCommandBuffer commands, const GpuScene& scene, VkPipelineLayout layout, VkDescriptorSet frame,
                const glm::vec3& background) const;
    const Texture& color() const { return color_; }
    const Texture& depth() const { return depth_; }

private:
    Texture color_;
    Texture depth_;
    std::unique_ptr<GraphicsPipeline> pipeline_;
};

}  // namespace canopy
