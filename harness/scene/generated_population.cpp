#include "scene/generated_population.hpp"

namespace canopy {

std::vector<GeneratedPopulation> generate_populations(const Scene& scene, const std::vector<TriangleMesh>& meshes,
                                                      const std::vector<std::string>& kinds) {
    std::vector<GeneratedPopulation> generated;
    for (size_t index : populations_of_kinds(scene.populations, kinds)) {
        const Population& population = scene.populations[index];
        generated.push_back(GeneratedPopulation{population.name, population.kind, population.prototype.material,
                                                population.prototype.casts_shadows,
                                                prototype_mesh(scene, meshes, index), PopulationCopies(generate_instances(population)),
                                                population.family ? population.family->vertex_data
                                                                  : std::vector<PopulationVertexData>{},
                                                population.params,
                                                population.family ? population.family->transmission : 0.0f,
                                                population.ground.terrain != nullptr});
    }
    return generated;
}

}  // namespace canopy
