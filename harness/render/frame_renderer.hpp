// Builds, from a technique's FramePlan, exactly the passes and resources it asks for, records
// one frame's commands once, and replays them: each render() is one timed frame.
#pragma once

#include "core/image.hpp"
#include "core/technique.hpp"
#include "gpu/pass_timer.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view.hpp"
#include "render/lit_pass.hpp"
#include "render/moment_map_pass.hpp"
#include "render/screen_shadow_pass.hpp"
#include "render/shadow_map_pass.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

struct FrameTiming {
    std::vector<double> pass_gpu_ms;  // per pass, in pass_names() order
    double gpu_ms = 0;                // first pass start to last pass end
    double wall_ms = 0;               // CPU: submit to fence signalled
};

struct MemoryUse {
    uint64_t technique_bytes = 0;  // resources the technique asked for (shadow maps, ...)
    uint64_t target_bytes = 0;     // camera colour and depth targets, the same for every technique
    uint64_t scene_bytes = 0;      // vertex and index buffers
};

// Why a plan cannot run on a device or scene, and what the user can change so that it can.
struct Unsupported {
    std::string reason;  // "scene 'spheres': this technique needs an area light ..."
    std::string hint;    // fits the cause: the scene's light for a scene, --device for a device
};

// Why `plan` cannot run on this device or scene, or nullopt when it can.
std::optional<Unsupported> check_supported(const GpuContext& gpu, const Scene& scene, const FramePlan& plan);
std::optional<std::string> unsupported_reason(const GpuContext& gpu, const Scene& scene, const FramePlan& plan);

class FrameRenderer {
public:
    FrameRenderer(const GpuContext& gpu, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                  uint32_t width, uint32_t height, const FramePlan& plan);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    FrameTiming render();
    Image read_color() const;  // the last rendered frame, linear RGB, A = 1
    // The last frame at its pixel centres (core/pixel_visibility.hpp): the visibility the lit pass
    // gave the shadow light (the colour target's alpha) and the view depth of the surface drawn
    // (from the depth target). Not timed.
    Image read_pixel_visibility() const;
    // Both, reading the colour target once.
    struct ColorAndVisibility {
        Image color, visibility;
    };
    ColorAndVisibility read_color_and_pixel_visibility() const;
    // Intermediate buffers of the last frame, for tests and debugging: the coarse map (R = depth;
    // needs ShadowMapNeeds::coarse_filters) and the screen-shadow buffer after its filters
    // (needs FramePlan::screen_shadow). Throw std::logic_error when the plan has none.
    Image read_coarse_map() const;
    Image read_screen_shadow() const;
    const std::vector<std::string>& pass_names() const { return timer_->pass_names(); }
    MemoryUse memory() const;
    size_t triangle_count() const { return scene_->triangle_count(); }
    // "compare-linear" when hardware 2x2 PCF sampling is bound, "nearest" for a plain depth map,
    // "linear-<format>" for a moment map, "" without any map.
    std::string shadow_sampler() const;

private:
    void create_descriptors();
    void bind_image(uint32_t binding, VkSampler sampler, VkImageView view, VkImageLayout layout);
    void record();

    const GpuContext& gpu_;
    FramePlan plan_;
    glm::vec3 background_;
    float near_plane_ = 0.0f, far_plane_ = 0.0f;  // the camera's, to turn stored depth into view depth
    MemoryLedger ledger_;
    std::unique_ptr<GpuScene> scene_;
    std::optional<LightView> light_view_;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout pipeline_layout_ = VK_NULL_HANDLE;
    VkDescriptorPool descriptor_pool_ = VK_NULL_HANDLE;
    VkDescriptorSet descriptor_set_ = VK_NULL_HANDLE;
    VkSampler nearest_sampler_ = VK_NULL_HANDLE;
    VkSampler compare_sampler_ = VK_NULL_HANDLE;
    VkSampler moment_sampler_ = VK_NULL_HANDLE;
    Buffer uniforms_;
    std::unique_ptr<ShadowMapPass> shadow_pass_;
    std::unique_ptr<MomentMapPass> moment_pass_;
    std::unique_ptr<FilterChain> coarse_map_;
    std::unique_ptr<ScreenShadowPass> screen_pass_;
    std::unique_ptr<LitPass> lit_pass_;
    std::unique_ptr<PassTimer> timer_;
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace canopy
