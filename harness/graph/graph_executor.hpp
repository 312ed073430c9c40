// Runs a FrameGraph: allocates its resources, builds each pass's descriptor set and pipeline
// layout from its declared uses, runs the load phase once, then records the frame phase anew
// every frame, with the barriers the uses imply, a timestamp pair around every GPU pass and a
// steady clock around every CPU pass.
#pragma once

#include "core/frame_state.hpp"
#include "gpu/pass_timer.hpp"
#include "gpu/primitive_counter.hpp"
#include "gpu/resources.hpp"
#include "graph/frame_graph.hpp"
#include "graph/graph_resources.hpp"
#include "graph/pipeline_cache.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace canopy {

class GpuScene;

// One phase's timing: GPU passes in gpu_pass_names() order, CPU passes in cpu_pass_names() order.
struct PhaseTiming {
    std::vector<double> pass_gpu_ms;
    std::vector<double> pass_cpu_ms;
    double gpu_ms = 0;         // first GPU pass start to last GPU pass end (timestamps)
    double wall_ms = 0;        // CPU: submit to fence signalled
    double record_cpu_ms = 0;  // CPU: recording the commands, CPU passes excluded
    uint64_t uploaded_bytes = 0;
    std::optional<PrimitiveCounts> primitives;  // when asked for and the device counts them
    std::vector<std::pair<std::string, double>> counters;  // CpuPassContext::count, in first-counted order
    std::vector<uint32_t> pass_draws;  // per GPU pass: the draw commands it recorded
};

class GraphExecutor {
public:
    // Throws std::logic_error when `graph` is malformed (validate()), naming the problem.
    GraphExecutor(const GpuContext& gpu, MemoryLedger& ledger, FrameGraph graph, uint32_t width, uint32_t height,
                  const Buffer& frame_uniforms, const GpuScene& scene);
    ~GraphExecutor();
    GraphExecutor(const GraphExecutor&) = delete;
    GraphExecutor& operator=(const GraphExecutor&) = delete;

    // Runs the load-phase passes (once; the constructor does not).
    PhaseTiming run_load(const FrameState& state);
    // Records, submits and waits for one frame; with `count_primitives`, counts the triangles its
    // passes submit and rasterise (PhaseTiming::primitives; not for timed frames).
    PhaseTiming run_frame(const FrameState& state, bool count_primitives = false);

    const std::vector<std::string>& gpu_pass_names(Phase phase) const { return phases_[int(phase)].gpu_names; }
    const std::vector<std::string>& cpu_pass_names(Phase phase) const { return phases_[int(phase)].cpu_names; }
    const FrameGraph& graph() const { return graph_; }
    GraphResources& resources() { return *resources_; }
    const GraphResources& resources() const { return *resources_; }
    size_t pipeline_count() const { return pipelines_->size(); }

    // Records into `commands` the barriers that bring `range` of `image` to `layout` (readbacks).
    void transition(VkCommandBuffer commands, GraphImage& image, const Subresource& range, VkImageLayout layout);

private:
    struct PassBinding;  // a pass's descriptor set and pipeline layout
    struct PhasePasses {
        std::vector<size_t> passes;  // indices into graph_.passes
        std::vector<std::string> gpu_names, cpu_names;
        std::unique_ptr<PassTimer> timer;
    };
    class Context;

    PhaseTiming run(Phase phase, const FrameState& state, bool count_primitives);
    void create_pass_bindings();
    VkSampler sampler(SamplerKind kind);
    void barriers_for(VkCommandBuffer commands, const PassDecl& pass);
    void record_pass(VkCommandBuffer commands, size_t index, Context& context);

    const GpuContext& gpu_;
    FrameGraph graph_;
    const GpuScene& scene_;
    uint32_t width_ = 0, height_ = 0;  // the camera target's
    std::unique_ptr<GraphResources> resources_;
    std::unique_ptr<PipelineCache> pipelines_;
    std::vector<std::unique_ptr<PassBinding>> bindings_;  // per pass
    std::array<PhasePasses, 2> phases_;
    std::unique_ptr<PrimitiveCounter> primitive_counter_;  // when the device has pipeline statistics
    std::array<VkSampler, 5> samplers_{};
    std::map<std::string, bool> buffer_written_;  // written since the last buffer barrier
    VkCommandPool command_pool_ = VK_NULL_HANDLE;
    VkCommandBuffer commands_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace canopy
