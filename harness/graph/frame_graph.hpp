// A technique's frame, declared as data (in the spirit of Falcor's RenderPass::reflect()): the
// images and buffers it needs and the passes that read and write them, in order. The harness
// allocates exactly what is declared, derives every barrier and descriptor binding from the
// declared uses, records the passes every frame and times each one (graph/graph_executor.hpp).
// Declaring needs no device, so tests check a technique's graph on any machine.
#pragma once

#include "core/shader_params.hpp"

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace canopy {

class PassContext;     // graph/pass_context.hpp: what a GPU pass may record
class CpuPassContext;  // graph/pass_context.hpp: what a CPU pass may do

// Names of the resources the harness provides to every graph.
namespace graph_names {
inline constexpr const char* kFrameUniforms = "frame";  // uniform buffer: harness/shaders/frame_uniforms.glsl
// RGBA32F camera target: rgb radiance, a = the shadow light's visibility. A pass that clears it
// gets the scene's background radiance as the clear rgb (its declared clear gives only alpha), and
// so does a multisampled colour attachment of a pass that resolves into it.
inline constexpr const char* kColor = "color";
inline constexpr const char* kDepth = "depth";          // D32F camera depth, stored (pixel-centre visibility)
}  // namespace graph_names

// An image's size: absolute texels, or the camera target's size divided by `divisor` (rounded up).
struct ImageExtent {
    enum class Rule { absolute, screen } rule = Rule::absolute;
    uint32_t width = 0, height = 0;  // absolute
    uint32_t divisor = 1;            // screen
    static ImageExtent square(uint32_t size) { return {Rule::absolute, size, size, 1}; }
    static ImageExtent texels(uint32_t width, uint32_t height) { return {Rule::absolute, width, height, 1}; }
    static ImageExtent screen(uint32_t divisor = 1) { return {Rule::screen, 0, 0, divisor}; }
};

struct ImageDecl {
    std::string name;
    VkFormat format = VK_FORMAT_UNDEFINED;
    ImageExtent extent;
    uint32_t layers = 1;
    uint32_t mips = 1;
    uint32_t samples = 1;     // 1 or 4 on lavapipe
    bool persistent = false;  // keeps its contents from frame to frame (and from the load phase)
    // Its views are 2D arrays even with one layer (layered images' always are): for shaders that
    // read it and layered images alike (image2DArray, sampler2DArray).
    bool arrayed = false;
};

enum BufferUsage : uint32_t {
    kVertexBuffer = 1u << 0,
    kIndexBuffer = 1u << 1,
    kStorageBuffer = 1u << 2,
    kIndirectBuffer = 1u << 3,
    kUniformBuffer = 1u << 4,
};

struct BufferDecl {
    std::string name;
    uint64_t bytes = 0;
    // Plus this much per copy of the scene's populations of the graph's kinds
    // (GraphNeeds::populations), counted when the graph is allocated: per-cell data, say.
    uint64_t bytes_per_copy = 0;
    uint32_t usage = 0;        // BufferUsage bits
    bool persistent = false;   // keeps its contents from frame to frame (and from the load phase)
    bool host_visible = false; // CPU passes write it directly (upload); else uploads go through a copy
    // Allocated only when one of the scene's populations stands on a terrain (what follows the
    // ground needs, a flat field does not): else 16 bytes, which the passes must not read (they
    // choose their shaders when recording, from GeneratedPopulation::on_terrain).
    bool only_on_terrain = false;
};

// How a pass uses a resource. Descriptor uses (sampled, storage, uniform) name the binding the
// pass's shaders declare; attachments are bound in the order they are listed.
enum class Use {
    sampled,           // image: combined image sampler
    storage_read,      // image (GENERAL) or storage buffer, read only
    storage_write,     // image (GENERAL) or storage buffer, written (and possibly read)
    color_attachment,  // image: raster target
    depth_attachment,  // image: raster depth target
    resolve_target,    // image: the single-sample image an MSAA colour attachment resolves into
    uniform,           // buffer: uniform block
    vertex,            // buffer: vertex or instance attributes
    index,             // buffer
    indirect,          // buffer: draw or dispatch arguments, draw counts
    transfer_read,     // copy source
    transfer_write,    // copy destination (uploads, fills, copies)
};

// linear_mipmap: trilinear; anisotropic: trilinear with up to 16 samples along a stretched
// footprint (GpuContext::max_anisotropy; trilinear where the device has none).
enum class SamplerKind { nearest, linear, linear_mipmap, compare_linear, anisotropic };

// A range of an image's mips and layers (all by default).
struct Subresource {
    uint32_t mip = 0, mip_count = ~0u;
    uint32_t layer = 0, layer_count = ~0u;
};

struct ResourceUse {
    std::string resource;
    Use use = Use::sampled;
    int binding = -1;                     // descriptor uses: the shader's binding in set 0
    SamplerKind sampler = SamplerKind::nearest;
    Subresource range;                    // images
    std::optional<std::array<float, 4>> clear;  // attachments: clear at the pass's start (else load)
    bool store = true;                    // depth attachments: keep the result (else discard)

    bool writes() const {
        return use == Use::storage_write || use == Use::color_attachment || use == Use::depth_attachment ||
               use == Use::resolve_target || use == Use::transfer_write;
    }
};

enum class PassKind { raster, compute, copy, cpu };
enum class Phase { load, frame };  // load: once, before the first frame, timed apart
const char* to_string(PassKind kind);
const char* to_string(Phase phase);

struct PassDecl {
    std::string name;  // timing label
    PassKind kind = PassKind::raster;
    Phase phase = Phase::frame;
    std::vector<ResourceUse> uses;
    uint32_t push_constant_bytes = 0;  // raster passes that draw the scene need sizeof(DrawConstants)
    // What configures the pass beyond its uses (shaders, radii, counts ...), as text: two passes
    // with the same settings record the same commands. Plans compare and print it.
    std::string settings;
    std::function<void(PassContext&)> record;  // GPU passes (raster, compute, copy)
    std::function<void(CpuPassContext&)> run;  // CPU passes
};

// What a graph needs of the scene and device beyond its resources' formats.
struct GraphNeeds {
    // The frame uniforms' light-view fields describe the shadow light seen by a map of this many
    // texels (render/light_view.hpp); unset: no light view (a scene without a shadow light runs).
    // A shared service, not the shadow family's: any pass that renders from the light uses it.
    std::optional<uint32_t> light_view_resolution;
    bool area_light = false;  // refuses scenes whose shadow light has no size
    // Population kinds (scene/population.hpp) the technique renders; a scene holding another is refused.
    std::vector<std::string> populations;
    // Whether those populations' copies (PopulationInstance records) are uploaded to the GPU. A
    // technique that draws copies only from buffers of its own (a CPU cull writing each frame's
    // selection) says false: the copies then stay on the CPU (PassContext::populations), and the
    // services that read the scene's copies (draw_population, draw_over_population) refuse them.
    bool population_copies_on_gpu = true;
    // Whether the technique draws those populations standing on a terrain (a population's
    // `terrain` key: copies lifted vertex by vertex, FamilyPopulation::vertex_offset). A scene
    // whose population stands on one is refused by a technique that does not.
    bool populations_on_terrain = false;
};

struct FrameGraph {
    std::vector<ImageDecl> images;
    std::vector<BufferDecl> buffers;
    std::vector<PassDecl> passes;  // in execution order within each phase
    GraphNeeds needs;
    ShaderParams shader_params;  // uploaded as frame.technique (and sample offsets)

    // Facts a technique reports about how it renders, recorded with its results (e.g.
    // "shadow_sampler": "compare-linear").
    std::map<std::string, std::string> report;

    const ImageDecl* image(const std::string& name) const;
    const BufferDecl* buffer(const std::string& name) const;
};

// The first inconsistency of `graph`: a use of an undeclared resource, a read before any write,
// an attachment on a non-raster pass, a pass without its callback, a duplicate name ...
// Empty when the graph is well formed. The harness refuses a malformed graph with this message.
std::string validate(const FrameGraph& graph);

// The whole declaration as text, one line per resource and pass (uses, settings): two graphs with
// the same description render the same frame. `canopy graph` prints it; tests compare it.
std::string describe(const FrameGraph& graph);

}  // namespace canopy
