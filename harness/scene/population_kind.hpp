// Population kinds that technique families define (Mitsuba-style plug-ins, like techniques):
// a kind has a name, typed and documented parameters read from the `params` table of a
// [[population]], and generates its copies from them once, when the scene is read. The
// raster side draws what it generated (PassContext::draw_population), the Embree reference
// traces the same triangles and asks the kind's alpha test, so both see the same surfaces.
// The harness's own "scatter" kind is read by scene_config directly and is not registered here.
#pragma once

#include "core/param.hpp"
#include "scene/geometry.hpp"
#include "scene/population.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace canopy {

// Eight floats per prototype vertex that a family's shaders read (VertexLayout::population(),
// locations 10-11), e.g. a grass blade's strip coordinates, density threshold and root.
struct PopulationVertexData {
    glm::vec4 data[2]{glm::vec4(0.0f), glm::vec4(0.0f)};
};
static_assert(sizeof(PopulationVertexData) == 32, "population.vert's layout reads two vec4 per vertex");

// What a kind generates from its parameters.
struct FamilyPopulation {
    TriangleMesh prototype;                        // local space
    std::vector<PopulationVertexData> vertex_data;  // one per prototype vertex, or empty (zeros)
    std::vector<PopulationInstance> instances;     // every copy
    // The reference's alpha test: whether copy `copy`'s prototype triangle `triangle` is opaque
    // at barycentrics (u, v), as the family's shaders cut it. Empty: everything is opaque.
    std::function<bool(uint32_t copy, uint32_t triangle, float u, float v)> opaque;
    // The reference's albedo scale at the same point (the family's shaders multiply the
    // material's albedo by the same). Empty: 1.
    std::function<float(uint32_t copy, uint32_t triangle, float u, float v)> albedo_scale;
    // The share of the light arriving from behind a surface that it transmits to the side seen
    // (Boulanger 2008 eq 4.1's gamma, for thin blades and leaves): shading adds gamma times the
    // irradiance the other side receives. 0: opaque, as every other surface.
    float transmission = 0.0f;
    // Where a copy's vertices leave the shared prototype (grass on a terrain: each blade lifted
    // onto the ground under its root), as an offset in the prototype's local space added before
    // the copy's model matrix; empty: every copy is the prototype moved by its matrix. The
    // reference then stores each copy's triangles apart.
    std::function<glm::vec3(uint32_t copy, uint32_t vertex)> vertex_offset;
};

class PopulationKind {
public:
    virtual ~PopulationKind() = default;
    virtual std::string name() const = 0;     // what `kind = "..."` says
    virtual std::string summary() const = 0;  // one line for `canopy list`
    // Bumped whenever the same parameters would generate different surfaces (part of the
    // reference cache's key).
    virtual int version() const = 0;
    virtual std::vector<ParamSpec> params() const = 0;
    // Deterministic in `params` and `ground`. Throws std::invalid_argument, saying which parameter
    // to change, for values that are each in range but together cannot be generated (or cannot
    // stand on this ground).
    virtual FamilyPopulation generate(const ParamSet& params, const PopulationGround& ground) const = 0;
};

class PopulationKindRegistry {
public:
    static PopulationKindRegistry& instance();
    void add(std::unique_ptr<PopulationKind> kind);  // throws std::logic_error on a duplicate name
    const PopulationKind* find(const std::string& name) const;  // nullptr when unknown
    std::vector<const PopulationKind*> all() const;             // sorted by name
    std::vector<std::string> names() const;

private:
    std::vector<std::unique_ptr<PopulationKind>> kinds_;
};

// In a family's .cpp:  static canopy::RegisterPopulationKind<GrassPopulation> registered;
template <typename T>
struct RegisterPopulationKind {
    RegisterPopulationKind() { PopulationKindRegistry::instance().add(std::make_unique<T>()); }
};

}  // namespace canopy
