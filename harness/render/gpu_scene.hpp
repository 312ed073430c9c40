// Scene geometry on the GPU: every object's mesh in one vertex and one index buffer, and a
// draw per object instance; and, for the populations of the kinds a graph declares it renders
// (GraphNeeds::populations), each prototype's mesh in the same buffers and a per-population
// buffer of its copies (PopulationInstance), drawn instanced. Other populations get nothing.
#pragma once

#include "gpu/resources.hpp"
#include "render/frame_uniforms.hpp"
#include "scene/generated_population.hpp"
#include "scene/geometry.hpp"

#include <cstdint>
#include <span>
#include <string>

#include <vector>

namespace canopy {

struct SceneDraw {
    uint32_t first_index = 0;
    uint32_t index_count = 0;
    int32_t vertex_offset = 0;
    bool casts_shadows = true;
    DrawConstants constants;
};

class GpuScene {
public:
    // `population_kinds`: the kinds the technique renders; only their populations are uploaded,
    // and their copies only with `copies_on_gpu` (GraphNeeds::population_copies_on_gpu).
    GpuScene(const GpuContext& gpu, MemoryLedger& ledger, const Scene& scene, const std::vector<TriangleMesh>& meshes,
             const std::vector<std::string>& population_kinds = {}, bool copies_on_gpu = true);

    // Binds the buffers and draws every instance (only shadow casters when `casters_only`).
    void draw(VkCommandBuffer commands, VkPipelineLayout layout, bool casters_only) const;
    // Summed over instances and the uploaded populations' copies (those of the technique's kinds).
    size_t triangle_count() const { return triangles_; }

    // The uploaded populations, in scene order.
    std::span<const GeneratedPopulation> populations() const { return populations_; }
    // One instanced draw of every copy of population `name` (VertexLayout::population), pushing
    // DrawConstants with an identity model and the prototype's albedo. Throws std::logic_error
    // naming the populations there are when `name` is not one of them.
    // `max_copies`: only the first copies (e.g. one, to bake the prototype).
    void draw_population(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                         uint32_t max_copies = UINT32_MAX) const;
    // The prototype alone, `instances` times (PassContext::draw_prototype): the copies' buffer (or,
    // without copies on the GPU, the vertices) is bound but must not be read.
    void draw_prototype(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                        uint32_t instances) const;
    // PassContext::population_draw_arguments and draw_population_indirect.
    VkDrawIndexedIndirectCommand draw_arguments(const std::string& name) const;
    void draw_population_indirect(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                                  VkBuffer copies, VkBuffer arguments) const;
    // Geometry a technique owns (`vertex_buffers` at bindings 0..n-1, `vertex_count` vertices)
    // drawn once per copy of population `name`, its PopulationInstance records at binding n.
    void draw_over_population(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                              std::span<const VkBuffer> vertex_buffers, uint32_t vertex_count) const;
    // PassContext::draw_over_population_indirect: `copies` at binding n, one VkDrawIndirectCommand
    // in `arguments`.
    void draw_over_population_indirect(VkCommandBuffer commands, VkPipelineLayout layout, const std::string& name,
                                       std::span<const VkBuffer> vertex_buffers, VkBuffer copies,
                                       VkBuffer arguments) const;

private:
    struct PopulationDraw {
        SceneDraw draw;
        uint32_t instance_count = 0;
        Buffer instances;
    };

    const PopulationDraw& population_draw(const std::string& name) const;  // throws naming the populations there are
    // population_draw(name), refused (std::logic_error) when its copies are not on the GPU.
    const PopulationDraw& population_draw_with_copies(const std::string& name) const;
    void draw_instances(VkCommandBuffer commands, VkPipelineLayout layout, const PopulationDraw& d,
                        uint32_t instances) const;

    Buffer vertices_;
    Buffer indices_;
    Buffer vertex_data_;  // PopulationVertexData parallel to vertices_, when populations are drawn
    std::vector<SceneDraw> draws_;
    size_t triangles_ = 0;
    std::vector<GeneratedPopulation> populations_;
    std::vector<PopulationDraw> population_draws_;  // parallel to populations_
};

}  // namespace canopy
