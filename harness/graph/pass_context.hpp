// The services a pass records with instead of raw Vulkan. The executor has already bound the
// pass's descriptor set (its declared descriptor uses), inserted the barriers its uses need and,
// for a raster pass, begun rendering into its declared attachments; a pass only picks pipelines
// and draws, dispatches or copies. Resources are named as the graph declares them.
#pragma once

#include "core/frame_state.hpp"
#include "graph/raster_state.hpp"
#include "scene/generated_population.hpp"

#include <glm/glm.hpp>
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

namespace canopy {

// Which of the scene's objects a scene draw covers.
enum class SceneFilter { all, shadow_casters };

class PassContext {
public:
    virtual ~PassContext() = default;
    virtual const FrameState& frame() const = 0;

    // A pipeline for this pass (cached: the same state returns the same pipeline, created once).
    virtual VkPipeline raster_pipeline(const RasterState& state) = 0;
    virtual VkPipeline compute_pipeline(std::span<const uint32_t> spirv) = 0;

    // Raster passes.
    virtual void bind(VkPipeline pipeline) = 0;
    // The scene's objects with the scene's vertex layout; each draw pushes its DrawConstants.
    virtual void draw_scene(SceneFilter filter) = 0;
    // The scene's populations of the kinds the graph declares (GraphNeeds::populations), in scene
    // order: name, kind, prototype mesh and every copy, as the reference sees them.
    virtual std::span<const GeneratedPopulation> populations() const = 0;
    // Every copy of population `name` in one instanced draw, with VertexLayout::population()
    // (harness/shaders/population.vert); pushes DrawConstants (identity model, the prototype's
    // albedo), so the pass declares sizeof(DrawConstants) push-constant bytes like draw_scene.
    // `max_copies`: only the first copies (one, to bake the prototype, say).
    virtual void draw_population(const std::string& name, uint32_t max_copies = UINT32_MAX) = 0;
    // The prototype of population `name` drawn `instances` times, however many copies there are
    // (none for a population without copies), for a pipeline whose layout reads no copy attributes (gl_InstanceIndex tells the draws
    // apart: a bake of the patch and its neighbours, say); pushes DrawConstants likewise.
    virtual void draw_prototype(const std::string& name, uint32_t instances) = 0;
    // What draw_population(name) draws, as an indexed-indirect record (index count, first index and
    // vertex offset in the scene's buffers, every copy as instances), for a compute pass that
    // writes its own record (a cull); zeros for a population with nothing to draw.
    virtual VkDrawIndexedIndirectCommand population_draw_arguments(const std::string& name) const = 0;
    // The prototype of population `name` as draw_population draws it, but its instances taken from
    // the technique's buffer `copies` (PopulationInstance records, e.g. a cull's survivors) and its
    // arguments from the technique's buffer `arguments` (one VkDrawIndexedIndirectCommand a GPU
    // pass wrote): no readback. Pushes DrawConstants likewise.
    virtual void draw_population_indirect(const std::string& name, const std::string& copies,
                                          const std::string& arguments) = 0;
    // Geometry the technique owns drawn once per copy of population `name` (billboards, impostor
    // boxes): its `vertex_buffers` at bindings 0..n-1, `vertex_count` vertices per copy, and the
    // copies' PopulationInstance records per instance at binding n
    // (VertexLayout::population_copies); pushes DrawConstants like draw_population.
    virtual void draw_over_population(const std::string& name, std::span<const std::string> vertex_buffers,
                                      uint32_t vertex_count) = 0;
    // The same geometry drawn over the copies in the technique's buffer `copies` (PopulationInstance
    // records, e.g. a cull's survivors), its vertex and instance counts read from the technique's
    // buffer `arguments` (one VkDrawIndirectCommand a GPU pass wrote): no readback.
    virtual void draw_over_population_indirect(const std::string& name, std::span<const std::string> vertex_buffers,
                                               const std::string& copies, const std::string& arguments) = 0;
    // Geometry the technique owns: vertex buffers bound in the pipeline's binding order.
    virtual void draw(std::span<const std::string> vertex_buffers, uint32_t vertex_count, uint32_t instance_count) = 0;
    virtual void draw_indexed(std::span<const std::string> vertex_buffers, const std::string& index_buffer,
                              uint32_t index_count, uint32_t instance_count) = 0;
    // The same, its vertex and instance counts read from the technique's buffer `arguments` (one
    // VkDrawIndirectCommand a CPU or GPU pass wrote this frame): a count a CPU pass chose, say.
    virtual void draw_indirect(std::span<const std::string> vertex_buffers, const std::string& arguments) = 0;
    // Draws whose arguments (VkDrawIndexedIndirectCommand records) and count a GPU pass wrote:
    // no CPU readback.
    virtual void draw_indexed_indirect_count(std::span<const std::string> vertex_buffers, const std::string& index_buffer,
                                             const std::string& arguments, const std::string& count,
                                             uint32_t max_draws) = 0;

    // Push constants for the next draw or dispatch (up to the pass's declared bytes).
    virtual void push_constants(const void* bytes, uint32_t size) = 0;

    // Compute passes.
    virtual void dispatch(VkPipeline pipeline, uint32_t groups_x, uint32_t groups_y, uint32_t groups_z) = 0;

    // Transfers (copy passes, and resets inside compute passes).
    virtual void fill(const std::string& buffer, uint32_t value) = 0;
    // Copies bytes into a buffer through a staging buffer; counted in the frame's uploaded bytes.
    virtual void upload(const std::string& buffer, const void* bytes, size_t size, size_t offset = 0) = 0;
    virtual void copy_buffer(const std::string& from, const std::string& to) = 0;
    // Copies tightly packed texels into one mip and layer of an image (transfer-write use);
    // counted in the uploaded bytes.
    virtual void upload_image(const std::string& image, const void* bytes, size_t size, uint32_t mip = 0,
                              uint32_t layer = 0) = 0;

    // The extent of an image's mip 0, as allocated.
    virtual VkExtent2D extent(const std::string& image) const = 0;
    // A host-visible buffer (BufferDecl::host_visible) as the CPU passes recorded before this one
    // left it this frame: e.g. a draw record a CPU cull wrote, to record no draw for a count of 0.
    virtual std::span<const std::byte> read(const std::string& buffer) const = 0;

    // For what the services do not cover yet; prefer adding a service.
    virtual VkCommandBuffer raw_commands() = 0;
};

// CPU passes run on the CPU when the frame is recorded, timed with a steady clock. A GPU resource
// they read holds what the previous frame (or the load phase) left in it.
class CpuPassContext {
public:
    virtual ~CpuPassContext() = default;
    virtual const FrameState& frame() const = 0;
    // The frame's world -> clip matrix, exactly the frame uniforms' view_proj (view_projection in
    // scene/camera.hpp), so a CPU cull for the GPU sees the frustum the shaders draw into.
    virtual glm::mat4 view_proj() const = 0;
    // A named count of this frame (cells a CPU cull kept, say), reported per case beside the
    // triangles, from the first warm-up frame (CaseResult::counters); a name counted twice in one
    // frame adds up.
    virtual void count(const std::string& name, double value) = 0;
    // As PassContext::populations: e.g. for a CPU cull of the copies.
    virtual std::span<const GeneratedPopulation> populations() const = 0;
    // As PassContext::population_draw_arguments: the record a CPU cull writes its count into.
    virtual VkDrawIndexedIndirectCommand population_draw_arguments(const std::string& name) const = 0;
    // Writes into a host-visible buffer (BufferDecl::host_visible); counted in the uploaded bytes.
    virtual void upload(const std::string& buffer, const void* bytes, size_t size, size_t offset = 0) = 0;
    // Reads a host-visible buffer as the GPU left it.
    virtual std::span<const std::byte> read(const std::string& buffer) const = 0;
};

}  // namespace canopy
