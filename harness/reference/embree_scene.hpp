// The scene as Embree sees it: one triangle geometry per object instance, with world-space
// vertices (objects' few instances are flattened, which traces fastest), and per population one
// prototype geometry in its own space, instanced once per copy (a grass field's 1024 to 200,000
// cells would not fit flattened: 24.6 M triangles for Lemme's Table 7.1 field).
//
// Two Embree scenes share the vertex and index buffers:
//   visible scene: every object, for camera rays;
//   shadow scene:  only objects with casts_shadows, for shadow rays (the same RTCScene when
//                  every object casts shadows).
// A geometry ID means the same object instance or population in both (see geometry()); a hit
// on a population's copy comes back from Embree as (instance, prototype triangle): resolve()
// turns it into the population's geometry ID and the copy's flattened primitive.
#pragma once

#include "scene/geometry.hpp"
#include "scene/scene.hpp"

#include "reference/shadow_packet.hpp"

#include <embree3/rtcore.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace canopy {

// Alpha testing hook for cut-out geometry (foliage, grass): called for every candidate hit of
// a camera or shadow ray on an object that has one, with the triangle index within the object's
// mesh and the hit's barycentric coordinates (u weights vertex 1, v weights vertex 2). Return
// true when the surface is opaque there (the hit stands), false to let the ray pass.
// Called concurrently from several threads: it must be thread-safe (pure is best).
using AlphaTest = std::function<bool(uint32_t triangle, float u, float v)>;

struct EmbreeSceneOptions {
    // Indexed like scene.objects; missing or empty entries are opaque objects.
    std::vector<AlphaTest> alpha_tests;
    // Indexed like scene.populations; the triangle index is within the prototype's mesh, the same
    // for every copy. Missing or empty entries are opaque prototypes.
    std::vector<AlphaTest> population_alpha_tests;
    // Embree's device configuration (rtcNewDevice), e.g. "isa=avx2" to force one code path;
    // empty: Embree picks the best ISA of this CPU. Embree takes its SSE2 path for an ISA name it
    // does not know, silently: check the packet widths with rtcGetDeviceProperty. Every ISA must
    // render the same image, so this is not in the reference cache key, and the cache
    // (run/reference_provider) never builds a scene with it.
    std::string device_config;
};

// What one geometry ID stands for: an object's instance, or (population >= 0) every copy of a
// population, copy k's triangles at (flattened) primitives [k * T, (k + 1) * T) for a
// T-triangle prototype.
struct EmbreeInstance {
    uint32_t object = 0;    // index into scene.objects (0 for a population)
    uint32_t instance = 0;  // index into that object's instances (0 for a population)
    int32_t population = -1;                 // index into scene.populations, or -1 for an object
    uint32_t prototype_triangles = 0;        // a population's T
};

// A ray's hit as the scene's objects and populations number it (EmbreeScene::resolve).
struct EmbreeHit {
    unsigned geometry = RTC_INVALID_GEOMETRY_ID;  // geometry(): an object instance or a population
    uint64_t primitive = 0;  // the triangle within it; a population's copy k, triangle t: k * T + t
    glm::vec3 geometric_normal{0.0f};  // world space, not unit; its sign not the winding's (a mirrored copy flips it)
};

class EmbreeScene {
public:
    // A population's alpha test per copy: (copy, prototype triangle, u, v) -> opaque.
    using CopyAlphaTest = std::function<bool(uint32_t copy, uint32_t triangle, float u, float v)>;
    // What a prototype geometry's filter reads (public for the filter function only): its test, and how to find the copy from the
    // instance ID Embree is traversing.
    struct CopyFilter {
        const CopyAlphaTest* test = nullptr;
        unsigned first_instance = 0;
    };
    // Throws ConfigError naming the object's file:line when an instance cannot be represented
    // (non-finite or degenerate transform, non-finite vertices, out-of-range indices).
    EmbreeScene(const Scene& scene, const std::vector<TriangleMesh>& meshes, const EmbreeSceneOptions& options = {});
    ~EmbreeScene();
    EmbreeScene(const EmbreeScene&) = delete;
    EmbreeScene& operator=(const EmbreeScene&) = delete;

    RTCDevice device() const { return device_; }
    RTCScene visible_scene() const { return visible_scene_; }
    RTCScene shadow_scene() const { return shadow_scene_; }
    // How shadow rays are handed to Embree: one ray at a time where a population's instanced
    // copies are cut by a filter function (shadow_packet.hpp: where Embree's 16-wide kernel was seen
    // to hang), else packets.
    ShadowQuery shadow_query() const {
        for (const Record& record : records_)
            if (record.instanced() && record.copy_alpha_test >= 0) return ShadowQuery::single;
        return ShadowQuery::packet16;
    }

    size_t geometry_count() const { return records_.size(); }
    // The hit of a ray that hit something (hit.geomID valid), in geometry() numbering.
    EmbreeHit resolve(const RTCHit& hit) const;
    const EmbreeInstance& geometry(unsigned geom_id) const { return records_[geom_id].instance; }
    const Material& material(unsigned geom_id) const { return records_[geom_id].material; }
    // The albedo at a hit: the material's, times a family population's albedo scale there
    // (FamilyPopulation::albedo_scale, as its shaders modulate it).
    glm::vec3 albedo(unsigned geom_id, uint64_t prim_id, float u, float v) const;
    // The share of the light from behind that the surface transmits (FamilyPopulation::transmission).
    float transmission(unsigned geom_id) const { return records_[geom_id].transmission; }
    // Interpolated vertex normal in world space (unit, not yet turned towards the viewer), as
    // the raster pipeline interpolates it.
    glm::vec3 shading_normal(unsigned geom_id, uint64_t prim_id, float u, float v) const;

    // Radius of the bounding sphere of all world-space vertices (0 for an empty scene).
    float extent() const { return extent_; }
    const Bounds& bounds() const { return bounds_; }
    // Every copy's triangles counted (what the rays see), and those Embree stores (a population's
    // prototype once).
    size_t triangle_count() const { return triangle_count_; }
    size_t stored_triangle_count() const { return stored_triangle_count_; }

private:
    struct Record {
        EmbreeInstance instance;
        Material material;
        bool casts_shadows = true;
        int alpha_test = -1;                    // an object's: index into alpha_tests_, or -1: opaque
        // A family population's (copy, prototype triangle, u, v) -> albedo factor, or empty.
        std::function<float(uint32_t, uint32_t, float, float)> albedo_scale;
        float transmission = 0.0f;              // a family population's, else 0
        std::vector<float> positions;           // xyz per vertex + 1 float of padding Embree may read
        std::vector<glm::vec3> normals;         // unit; world space, or a population's prototype space
        std::shared_ptr<const std::vector<uint32_t>> indices;
        // A population: its copies' transforms, whose instances hold geometry IDs
        // [first_instance, first_instance + copies) in the top-level scenes, and its test.
        std::vector<glm::mat4> copy_models;
        // A family's copies whose vertices leave the prototype (FamilyPopulation::vertex_offset):
        // each copy's own positions, prototype space (same layout as `positions`); empty: shared.
        std::vector<std::vector<float>> copy_positions;
        std::vector<glm::mat3> copy_normal_matrices;  // turn prototype normals into world space
        unsigned first_instance = 0;
        int copy_alpha_test = -1;  // index into copy_alpha_tests_, or -1: opaque
        bool instanced() const { return instance.population >= 0; }
    };

    void add_population(const Scene& scene, const std::vector<TriangleMesh>& meshes, size_t index,
                        const EmbreeSceneOptions& options);
    void build_embree_scenes(const std::string& device_config);
    RTCGeometry create_geometry(const Record& record, const AlphaTest* alpha_test, const CopyFilter* copy_filter,
                                const std::vector<float>* positions = nullptr) const;
    // Instances of `prototype` for copies [first, first + count) of the record.
    void attach_copies(const Record& record, RTCScene prototype, size_t first, size_t count);
    void release();

    RTCDevice device_ = nullptr;
    RTCScene visible_scene_ = nullptr;
    RTCScene shadow_scene_ = nullptr;
    std::vector<RTCScene> prototype_scenes_;  // one per population
    std::vector<Record> records_;
    std::vector<unsigned> instance_owner_;    // the record of instance ID first_instance_id_ + i
    unsigned first_instance_id_ = 0;
    // Objects' tests, reserved up front, so their addresses stay stable for Embree's user data.
    std::vector<AlphaTest> alpha_tests_;
    std::vector<CopyAlphaTest> copy_alpha_tests_;  // populations' (reserved: stable addresses)
    std::vector<CopyFilter> copy_filters_;         // one per population, reserved likewise
    Bounds bounds_;
    float extent_ = 0.0f;
    size_t triangle_count_ = 0;
    size_t stored_triangle_count_ = 0;
};

}  // namespace canopy
