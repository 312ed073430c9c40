// The fixed-function state of a raster pipeline a pass asks the pipeline cache for: shaders,
// vertex layout, depth, blending, alpha-to-coverage. Attachment formats and the sample count come
// from the pass's declared attachments. Pure data.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace canopy {

// Vertex input: buffers (per vertex or per instance) and the attributes read from them.
struct VertexLayout {
    struct Binding {
        uint32_t stride = 0;
        bool per_instance = false;
    };
    struct Attribute {
        uint32_t location = 0;
        uint32_t binding = 0;
        VkFormat format = VK_FORMAT_R32G32B32_SFLOAT;
        uint32_t offset = 0;
    };
    std::vector<Binding> bindings;
    std::vector<Attribute> attributes;

    // The scene's vertices (scene/geometry.hpp Vertex): location 0 position, 1 normal.
    static VertexLayout scene();
    // A population's instanced draw (PassContext::draw_population): the scene's vertices at
    // binding 0, and per instance (binding 1) a PopulationInstance (scene/population.hpp): its
    // model matrix at locations 2-5, its normal matrix's columns at 6-8, its data at 9; and per
    // vertex (binding 2) the kind's PopulationVertexData (scene/population_kind.hpp) at 10-11.
    static VertexLayout population();
    // Appends the per-instance binding of a population's copies (PassContext::draw_over_population):
    // a PopulationInstance per instance, its model matrix at locations 2-5, its normal matrix's
    // columns at 6-8, its data at 9, as in population().
    VertexLayout& population_copies();
    // Appends a per-instance binding whose mat4 occupies four vec4 locations from `first_location`
    // at byte `offset` of a `stride`-byte record.
    VertexLayout& instance_mat4(uint32_t first_location, uint32_t stride, uint32_t offset = 0);
    std::string describe() const;
};

enum class Blend { none, alpha, additive };

struct RasterState {
    std::span<const uint32_t> vertex_spirv;
    std::span<const uint32_t> fragment_spirv;  // empty: depth-only
    VertexLayout vertices = VertexLayout::scene();
    VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkCullModeFlags cull = VK_CULL_MODE_NONE;  // scenes hold open surfaces (planes)
    bool depth_test = true;
    bool depth_write = true;
    VkCompareOp depth_compare = VK_COMPARE_OP_LESS;
    Blend blend = Blend::none;       // the same for every colour attachment
    // Needs a multisampled pass to mean more than an alpha test; the covered samples store alpha 1
    // where the device has alphaToOne (GpuContext::alpha_to_one), as lavapipe and NVIDIA do.
    bool alpha_to_coverage = false;
    // The fragment shader runs once per covered sample (minSampleShading 1; a shader whose inputs
    // carry the `sample` qualifier does so anyway, and needs this to say so): the device must offer
    // sampleRateShading (GpuContext::sample_rate_shading), else the pipeline is refused.
    bool sample_shading = false;
};

}  // namespace canopy
