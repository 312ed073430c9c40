#include "grass_cull.hpp"

#include "grass_passes.hpp"
#include "grass_population.hpp"
#include "patch_bake.hpp"

#include "../shaders/grass_culling.h"

#include <algorithm>

namespace canopy::grass {

void declare_grass_cull(FrameGraph& g, std::span<const uint32_t> cull_spirv) {
    using namespace cull_names;
    g.buffers.push_back({.name = kCull, .bytes = sizeof(shader::GrassCull), .usage = kUniformBuffer, .persistent = true});
    g.buffers.push_back({.name = kCopies, .bytes_per_copy = sizeof(PopulationInstance), .usage = kStorageBuffer,
                         .persistent = true});
    g.buffers.push_back({.name = kSurvivors, .bytes_per_copy = sizeof(PopulationInstance),
                         .usage = kStorageBuffer | kVertexBuffer});
    g.buffers.push_back({.name = kArguments, .bytes = sizeof(VkDrawIndexedIndirectCommand),
                         .usage = kStorageBuffer | kIndirectBuffer});

    PassDecl setup{.name = "cull_setup", .kind = PassKind::copy, .phase = Phase::load};
    setup.uses = {use(kCull, Use::transfer_write), use(kCopies, Use::transfer_write)};
    setup.settings = "the first grass population's copies";
    setup.record = [](PassContext& pc) {
        const GeneratedPopulation* grass = first_grass(pc.populations());
        shader::GrassCull cull{};
        if (grass && !grass->instances.empty()) {
            const Bounds bounds = prototype_bounds(grass);
            const VkDrawIndexedIndirectCommand draw = pc.population_draw_arguments(grass->name);
            cull.box_min = glm::vec4(bounds.min, 0.0f);
            cull.box_max = glm::vec4(bounds.max, 0.0f);
            cull.draw = glm::uvec4(draw.indexCount, draw.firstIndex, uint32_t(draw.vertexOffset), draw.instanceCount);
            pc.upload(kCopies, grass->instances.data(), grass->instances.size() * sizeof(PopulationInstance));
        }
        pc.upload(kCull, &cull, sizeof(cull));
    };
    g.passes.push_back(std::move(setup));

    PassDecl cull{.name = "cull", .kind = PassKind::compute};
    cull.uses = {use(graph_names::kFrameUniforms, Use::uniform, 0), use(kCull, Use::uniform, 1),
                 use(kCopies, Use::storage_read, 2), use(kSurvivors, Use::storage_write, 3),
                 use(kArguments, Use::storage_write, 4)};
    cull.settings = "frustum and distance, one invocation per copy";
    cull.record = [spirv = cull_spirv](PassContext& pc) {  // the generated SPIR-V is static
        const GeneratedPopulation* grass = first_grass(pc.populations());
        // The count restarts at 0 by a fill before the dispatch, not by a barrier inside a workgroup.
        pc.fill(kArguments, 0);
        const uint32_t copies = grass ? uint32_t(grass->instances.size()) : 0;
        pc.dispatch(pc.compute_pipeline(spirv), std::max(1u, (copies + 63) / 64), 1, 1);
    };
    g.passes.push_back(std::move(cull));
}

void use_cull_survivors(PassDecl& pass) {
    pass.uses.push_back(use(cull_names::kSurvivors, Use::vertex));
    pass.uses.push_back(use(cull_names::kArguments, Use::indirect));
}

void draw_populations_culled(PassContext& pc) {
    const GeneratedPopulation* first = first_grass(pc.populations());
    for (const GeneratedPopulation& population : pc.populations()) {
        // The cull covers the first grass population; others are drawn whole.
        if (&population == first)
            pc.draw_population_indirect(population.name, cull_names::kSurvivors, cull_names::kArguments);
        else
            pc.draw_population(population.name);
    }
}

}  // namespace canopy::grass
