#include "grass_cull.hpp"

#include "grass_passes.hpp"
#include "grass_population.hpp"
#include "patch_bake.hpp"

#include "../shaders/grass_culling.h"

#include "shaders/grass/grass_cull_comp.h"

#include <algorithm>
#include <array>
#include <fmt/format.h>

namespace canopy::grass {

void declare_grass_cull(FrameGraph& g, const std::vector<CullBand>& bands) {
    g.buffers.push_back({.name = kCullCopies, .bytes_per_copy = sizeof(PopulationInstance), .usage = kStorageBuffer,
                         .persistent = true});
    PassDecl setup{.name = "cull_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(kCullCopies, Use::transfer_write)};
    setup.settings = "the first grass population's copies";
    for (const CullBand& band : bands) {
        const CullNames names(band.prefix);
        g.buffers.push_back({.name = names.block, .bytes = sizeof(shader::GrassCull), .usage = kUniformBuffer,
                             .persistent = true});
        g.buffers.push_back({.name = names.survivors, .bytes_per_copy = sizeof(PopulationInstance),
                             .usage = kStorageBuffer | kVertexBuffer});
        g.buffers.push_back({.name = names.arguments, .bytes = sizeof(VkDrawIndexedIndirectCommand),
                             .usage = kStorageBuffer | kIndirectBuffer});
        setup.uses.push_back(use(names.block, Use::transfer_write));
    }
    setup.record = [bands](PassContext& pc) {
        const GeneratedPopulation* grass = first_grass(pc.populations());
        const bool any = grass && !grass->instances.empty();
        if (any) pc.upload(kCullCopies, grass->instances.data(), grass->instances.size() * sizeof(PopulationInstance));
        for (const CullBand& band : bands) {
            shader::GrassCull cull{};
            if (any) {
                Bounds bounds = prototype_bounds(grass);
                // On a terrain the blades rise above their cell's (x0, z0) corner by up to the
                // other corners' heights (grass_terrain.h): the box, in patch space, grows by that.
                float low = 0.0f, high = 0.0f;
                for (const PopulationInstance& copy : grass->instances)
                    for (int corner = 0; corner < 3; ++corner) {
                        const float lift = copy.normal_matrix[corner].w / copy.model[1][1];
                        low = std::min(low, lift);
                        high = std::max(high, lift);
                    }
                bounds.min.y += low;
                bounds.max.y += high;
                cull.box_min = glm::vec4(bounds.min, 0.0f);
                cull.box_max = glm::vec4(bounds.max, 0.0f);
                if (band.vertex_count == 0) {
                    const VkDrawIndexedIndirectCommand draw = pc.population_draw_arguments(grass->name);
                    cull.draw = glm::uvec4(draw.indexCount, draw.firstIndex, uint32_t(draw.vertexOffset), draw.instanceCount);
                } else {
                    // (vertex count, 0, 0): the record's first words read as a VkDrawIndirectCommand.
                    const uint32_t vertices = grass_on_terrain(pc.populations()) && band.vertex_count_on_terrain > 0
                                                  ? band.vertex_count_on_terrain
                                                  : band.vertex_count;
                    cull.draw = glm::uvec4(vertices, 0u, 0u, uint32_t(grass->instances.size()));
                }
                cull.distances = glm::vec4(band.min_distance, band.max_distance, 0.0f, 0.0f);
            }
            pc.upload(CullNames(band.prefix).block, &cull, sizeof(cull));
        }
    };
    g.passes.push_back(std::move(setup));

    for (const CullBand& band : bands) {
        const CullNames names(band.prefix);
        PassDecl cull{.name = names.pass, .kind = PassKind::compute};
        cull.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(names.block, Use::uniform, 1),
                     use(kCullCopies, Use::storage_read, 2), use(names.survivors, Use::storage_write, 3),
                     use(names.arguments, Use::storage_write, 4)};
        cull.settings = band.max_distance > 0.0f || band.min_distance > 0.0f
                            ? fmt::format("frustum, boxes within {}-{}, one invocation per copy", band.min_distance,
                                          band.max_distance > 0.0f ? fmt::format("{}", band.max_distance) : "any")
                            : "frustum, one invocation per copy";
        cull.record = [arguments = names.arguments](PassContext& pc) {
            const GeneratedPopulation* grass = first_grass(pc.populations());
            // The count restarts at 0 by a fill before the dispatch, not by a barrier inside a workgroup.
            pc.fill(arguments, 0);
            const uint32_t copies = grass ? uint32_t(grass->instances.size()) : 0;
            pc.dispatch(pc.compute_pipeline(grass_cull_comp), std::max(1u, (copies + 63) / 64), 1, 1);
        };
        g.passes.push_back(std::move(cull));
    }
}

void use_cull_survivors(PassDecl& pass, const std::string& prefix) {
    const CullNames names(prefix);
    pass.uses.push_back(use(names.survivors, Use::vertex));
    pass.uses.push_back(use(names.arguments, Use::indirect));
}

void draw_populations_culled(PassContext& pc, const std::string& prefix) {
    const CullNames names(prefix);
    const GeneratedPopulation* first = first_grass(pc.populations());
    for (const GeneratedPopulation& population : pc.populations()) {
        // The cull covers the first grass population; others are drawn whole.
        if (&population == first)
            pc.draw_population_indirect(population.name, names.survivors, names.arguments);
        else
            pc.draw_population(population.name);
    }
}

void record_copies_culled(PassContext& pc, const RasterState& over, const std::string& vertex_buffer,
                          uint32_t vertex_count, const std::optional<std::string>& culled_by) {
    if (!culled_by) return record_copies(pc, over, vertex_buffer, vertex_count);
    const CullNames names(*culled_by);
    pc.bind(pc.raster_pipeline(over));
    const std::array<std::string, 1> buffers{vertex_buffer};
    const GeneratedPopulation* first = first_grass(pc.populations());
    for (const GeneratedPopulation& population : pc.populations()) {
        if (&population == first)
            pc.draw_over_population_indirect(population.name, buffers, names.survivors, names.arguments);
        else
            pc.draw_over_population(population.name, buffers, vertex_count);
    }
}

}  // namespace canopy::grass
