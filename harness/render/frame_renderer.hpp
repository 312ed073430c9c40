// Renders a technique's FrameGraph (graph/frame_graph.hpp) over a scene: the scene's geometry and
// the frame uniforms are the harness's; everything else is what the graph declares. The load
// phase runs once at construction; each render() records and runs one timed frame.
#pragma once

#include "core/frame_state.hpp"
#include "core/image.hpp"
#include "graph/frame_graph.hpp"
#include "graph/graph_executor.hpp"
#include "render/gpu_scene.hpp"
#include "render/light_view.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

struct FrameTiming {
    std::vector<double> pass_gpu_ms;  // per GPU pass, in pass_names() order
    double gpu_ms = 0;                // first GPU pass start to last GPU pass end
    double wall_ms = 0;               // CPU: submit to fence signalled
    std::vector<double> pass_cpu_ms;  // per CPU pass, in cpu_pass_names() order
    double record_cpu_ms = 0;         // CPU: recording the frame's commands (CPU passes excluded)
    uint64_t uploaded_bytes = 0;      // moved from the CPU into buffers by the frame's passes
    std::optional<PrimitiveCounts> primitives;  // triangles submitted and rasterised, when counted
    std::vector<std::pair<std::string, double>> counters;  // the CPU passes' named counts (CpuPassContext::count)
    std::vector<uint32_t> pass_draws;  // per GPU pass, in pass_names() order: the draw commands it recorded
};

struct MemoryUse {
    uint64_t technique_bytes = 0;  // resources the technique declared (shadow maps, ...) that its frames use
    uint64_t target_bytes = 0;     // camera colour and depth targets, the same for every technique
    uint64_t scene_bytes = 0;      // vertex and index buffers
    // The most the technique's resources held at once: in the load phase, before what only it
    // used was released (GraphExecutor::run_load). At least technique_bytes.
    uint64_t technique_peak_bytes = 0;
};

// Why a graph cannot run on a device or scene, and what the user can change so that it can.
struct Unsupported {
    std::string reason;  // "scene 'spheres': this technique needs an area light ..."
    std::string hint;    // fits the cause: the scene's light for a scene, --device for a device
};

// Why `graph` cannot run on this device or scene, or nullopt when it can.
std::optional<Unsupported> check_supported(const GpuContext& gpu, const Scene& scene, const FrameGraph& graph);
// Its checks that need no device (the graph's shape, the scene's populations and light), which
// check_supported makes first: `canopy plan` makes these alone.
std::optional<Unsupported> check_scene_supported(const Scene& scene, const FrameGraph& graph);
// The other way round from the populations check_scene_supported refuses: a technique made to
// render a population kind, on a scene holding none of it, would time and score the scene's
// objects alone. Experiments refuse it (prepare_experiment, `canopy plan`); a renderer still draws
// such a graph, as tests do.
std::optional<Unsupported> check_population_present(const Scene& scene, const FrameGraph& graph);
std::optional<std::string> unsupported_reason(const GpuContext& gpu, const Scene& scene, const FrameGraph& graph);

class FrameRenderer {
public:
    FrameRenderer(const GpuContext& gpu, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                  uint32_t width, uint32_t height, FrameGraph graph);
    ~FrameRenderer();
    FrameRenderer(const FrameRenderer&) = delete;
    FrameRenderer& operator=(const FrameRenderer&) = delete;

    // One frame from the scene's camera, the frame index counting up from 0.
    FrameTiming render();
    // One frame in `state` (its camera, its frame index).
    FrameTiming render(const FrameState& state);
    // The same, counting the triangles the frame submits and rasterises when the device can
    // (FrameTiming::primitives); for untimed frames.
    FrameTiming render_counting_primitives(const FrameState& state);
    // The load phase's timing (run once, at construction), pass names in load_pass_names().
    const FrameTiming& load_timing() const { return load_timing_; }

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
    // Any image the graph declares, one mip and layer, as RGBA floats (R32F, RG32F, RGBA32F,
    // RGBA16F and D32F images), for tests and debugging. Throws std::logic_error for unknown names.
    Image read_image(const std::string& name, uint32_t mip = 0, uint32_t layer = 0) const;
    // The bytes of a buffer the graph declares (tests check what GPU passes wrote).
    std::vector<std::byte> read_buffer(const std::string& name) const;

    const std::vector<std::string>& pass_names() const { return executor_->gpu_pass_names(Phase::frame); }
    const std::vector<std::string>& cpu_pass_names() const { return executor_->cpu_pass_names(Phase::frame); }
    const std::vector<std::string>& load_pass_names() const { return executor_->gpu_pass_names(Phase::load); }
    const std::vector<std::string>& load_cpu_pass_names() const { return executor_->cpu_pass_names(Phase::load); }
    MemoryUse memory() const;
    size_t triangle_count() const { return scene_->triangle_count(); }
    size_t pipeline_count() const { return executor_->pipeline_count(); }
    // What the graph reported as "shadow_sampler" ("compare-linear", "nearest", "linear-<format>"),
    // "" when it reports none.
    std::string shadow_sampler() const;

private:
    void write_uniforms(const Camera& camera);
    FrameTiming render_frame(const FrameState& state, bool count_primitives);

    const GpuContext& gpu_;
    Scene scene_description_;  // its camera, lights and ambient fill the frame uniforms
    uint32_t width_, height_;
    MemoryLedger ledger_;
    std::unique_ptr<GpuScene> scene_;
    std::optional<LightView> light_view_;
    std::optional<uint32_t> light_view_resolution_;
    ShaderParams shader_params_;
    Buffer uniforms_;
    std::unique_ptr<GraphExecutor> executor_;
    FrameTiming load_timing_;
    uint32_t next_frame_ = 0;
    float near_plane_ = 0, far_plane_ = 0;  // of the last frame's camera: stored depth to view depth
};

}  // namespace canopy
