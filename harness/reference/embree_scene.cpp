#include "reference/embree_scene.hpp"

#include "alpha_mask.h"

#include "core/error.hpp"
#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace canopy {

namespace {

const char* embree_error_name(RTCError error) {
    switch (error) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_UNKNOWN: return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "unrecognised error";
}

void throw_if_embree_failed(RTCDevice device, const char* what) {
    const RTCError error = rtcGetDeviceError(device);
    if (error != RTC_ERROR_NONE)
        throw std::runtime_error(fmt::format("Embree failed while {}: {}", what, embree_error_name(error)));
}

bool is_finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

// Appends `mesh`'s vertices moved into world space by `model` (normals by `normal_matrix`, unit
// length) to `positions` and `normals`, and grows `bounds`. False when a position is not finite.
bool append_world_vertices(const TriangleMesh& mesh, const glm::mat4& model, const glm::mat3& normal_matrix,
                           std::vector<float>& positions, std::vector<glm::vec3>& normals, Bounds& bounds) {
    for (const Vertex& vertex : mesh.vertices) {
        const glm::vec3 world = glm::vec3(model * glm::vec4(vertex.position, 1.0f));
        if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z)) return false;
        positions.insert(positions.end(), {world.x, world.y, world.z});
        bounds.extend(world);
        const glm::vec3 normal = normal_matrix * vertex.normal;
        const float length = glm::length(normal);
        normals.push_back(length > 0.0f && std::isfinite(length) ? normal / length : glm::vec3(0.0f));
    }
    return true;
}

// Discards hits the object's alpha test calls transparent; serves camera and shadow rays alike.
void alpha_test_filter(const RTCFilterFunctionNArguments* args) {
    const AlphaTest& alpha_test = *static_cast<const AlphaTest*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (!alpha_test(triangle, u, v)) args->valid[i] = 0;
    }
}

// The same for a population's prototype: the copy is the instance Embree is traversing.
void copy_alpha_test_filter(const RTCFilterFunctionNArguments* args) {
    const auto& filter = *static_cast<const EmbreeScene::CopyFilter*>(args->geometryUserPtr);
    const uint32_t copy = args->context->instID[0] - filter.first_instance;
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] != -1) continue;
        const unsigned triangle = RTCHitN_primID(args->hit, args->N, i);
        const float u = RTCHitN_u(args->hit, args->N, i);
        const float v = RTCHitN_v(args->hit, args->N, i);
        if (!(*filter.test)(copy, triangle, u, v)) args->valid[i] = 0;
    }
}

}  // namespace

EmbreeScene::EmbreeScene(const Scene& scene, const std::vector<TriangleMesh>& meshes,
                         const EmbreeSceneOptions& options) {
    if (meshes.size() != scene.objects.size() + scene.populations.size())
        throw std::invalid_argument(fmt::format("EmbreeScene: {} meshes for {} scene objects and {} populations",
                                                meshes.size(), scene.objects.size(), scene.populations.size()));
    alpha_tests_.reserve(scene.objects.size());
    copy_alpha_tests_.reserve(scene.populations.size());
    copy_filters_.reserve(scene.populations.size());

    // Flatten every object instance into world space.
    for (size_t object_index = 0; object_index < scene.objects.size(); ++object_index) {
        const Object& object = scene.objects[object_index];
        const TriangleMesh& mesh = meshes[object_index];
        int alpha_test = -1;
        if (object_index < options.alpha_tests.size() && options.alpha_tests[object_index]) {
            alpha_tests_.push_back(options.alpha_tests[object_index]);
            alpha_test = int(alpha_tests_.size() - 1);
        }
        const auto reject = [&](size_t instance, const std::string& message) {
            return ConfigError(object.where.file, object.where.line,
                               fmt::format("the reference renderer cannot represent object '{}' (instance {}): {}",
                                           object.name, instance, message));
        };
        if (mesh.triangle_count() == 0) continue;
        for (uint32_t index : mesh.indices)
            if (index >= mesh.vertices.size())
                throw reject(0, fmt::format("its mesh references vertex {} of {}", index, mesh.vertices.size()));
        auto indices = std::make_shared<const std::vector<uint32_t>>(mesh.indices.begin(),
                                                                      mesh.indices.begin() + mesh.triangle_count() * 3);
        for (size_t instance_index = 0; instance_index < object.instances.size(); ++instance_index) {
            const glm::mat4 model = object.instances[instance_index].matrix();
            const glm::mat3 linear(model);
            const float determinant = glm::determinant(linear);
            if (!is_finite(model) || !std::isfinite(determinant))
                throw reject(instance_index, "its transform is not finite");
            if (std::abs(determinant) < 1e-12f)
                throw reject(instance_index, "its transform is degenerate (a zero scale flattens it)");
            const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));

            Record record;
            record.instance = {uint32_t(object_index), uint32_t(instance_index)};
            record.material = object.material;
            record.casts_shadows = object.casts_shadows;
            record.alpha_test = alpha_test;
            record.indices = indices;
            record.positions.reserve(mesh.vertices.size() * 3 + 1);
            record.normals.reserve(mesh.vertices.size());
            if (!append_world_vertices(mesh, model, normal_matrix, record.positions, record.normals, bounds_))
                throw reject(instance_index, "a vertex position is not finite");
            record.positions.push_back(0.0f);  // Embree loads vertices with 16-byte reads
            triangle_count_ += mesh.triangle_count();
            stored_triangle_count_ += mesh.triangle_count();
            records_.push_back(std::move(record));
        }
    }
    for (size_t population = 0; population < scene.populations.size(); ++population)
        add_population(scene, meshes, population, options);
    extent_ = bounds_.radius();

    try {
        build_embree_scenes(options.device_config);
    } catch (...) {
        release();
        throw;
    }
}

// One prototype geometry in its own space for all of a population's copies (generate_instances,
// as the raster side draws them), instanced once per copy.
void EmbreeScene::add_population(const Scene& scene, const std::vector<TriangleMesh>& meshes, size_t index,
                                 const EmbreeSceneOptions& options) {
    const Population& population = scene.populations[index];
    const TriangleMesh& mesh = prototype_mesh(scene, meshes, index);
    const auto reject = [&](size_t copy, const std::string& message) {
        return ConfigError(population.where.file, population.where.line,
                           fmt::format("the reference renderer cannot represent population '{}' (copy {}): {}",
                                       population.name, copy, message));
    };
    const size_t triangles = mesh.triangle_count();
    if (triangles == 0) return;
    for (uint32_t vertex : mesh.indices)
        if (vertex >= mesh.vertices.size())
            throw reject(0, fmt::format("its prototype's mesh references vertex {} of {}", vertex, mesh.vertices.size()));

    Record record;
    record.instance.population = int32_t(index);
    record.instance.prototype_triangles = uint32_t(triangles);
    record.material = population.prototype.material;
    record.casts_shadows = population.prototype.casts_shadows;
    // A copy's ray passes where the family's kind cuts that copy, or the scene's alpha mask
    // (alpha_mask.h, as population.vert and population_alpha.glsl cut it), or the caller's test says so.
    AlphaTest caller;
    if (index < options.population_alpha_tests.size()) caller = options.population_alpha_tests[index];
    const glm::vec4 mask = population.alpha_mask.packed();
    const bool masked = population.alpha_mask.kind != AlphaMask::Kind::none;
    if (population.family) {
        record.albedo_scale = population.family->albedo_scale;
        record.transmission = population.family->transmission;
        if (population.family->opaque || caller) {
            copy_alpha_tests_.push_back([caller, opaque = population.family->opaque](uint32_t copy, uint32_t triangle,
                                                                                    float u, float v) {
                if (opaque && !opaque(copy, triangle, u, v)) return false;
                return !caller || caller(triangle, u, v);
            });
            record.copy_alpha_test = int(copy_alpha_tests_.size() - 1);
        }
    } else if (masked || caller) {
        std::vector<glm::vec3> corners;  // the prototype's triangles in its mesh space
        if (masked) {
            corners.reserve(mesh.indices.size());
            for (uint32_t vertex : mesh.indices) corners.push_back(mesh.vertices[vertex].position);
        }
        copy_alpha_tests_.push_back([caller, masked, mask, corners = std::move(corners)](uint32_t, uint32_t triangle,
                                                                                        float u, float v) {
            if (masked) {
                const glm::vec3 p = (1.0f - u - v) * corners[3 * triangle] + u * corners[3 * triangle + 1] +
                                    v * corners[3 * triangle + 2];
                if (!shader::alpha_mask_opaque(mask, p)) return false;
            }
            return !caller || caller(triangle, u, v);
        });
        record.copy_alpha_test = int(copy_alpha_tests_.size() - 1);
    }

    // The prototype as it is, and its box, whose corners bound every copy.
    Bounds prototype_bounds;
    record.indices = std::make_shared<const std::vector<uint32_t>>(mesh.indices.begin(),
                                                                    mesh.indices.begin() + triangles * 3);
    record.positions.reserve(mesh.vertices.size() * 3 + 1);
    record.normals.reserve(mesh.vertices.size());
    if (!append_world_vertices(mesh, glm::mat4(1.0f), glm::mat3(1.0f), record.positions, record.normals,
                               prototype_bounds))
        throw reject(0, "a vertex position of its prototype is not finite");
    record.positions.push_back(0.0f);  // Embree loads vertices with 16-byte reads

    const auto shared_copies = generate_instances(population);
    const std::vector<PopulationInstance>& copies = *shared_copies;
    // Copies that leave the prototype (grass on a terrain) keep their own positions, and their box
    // grows by the most any copy moves a vertex.
    const auto& vertex_offset = population.family ? population.family->vertex_offset : nullptr;
    if (vertex_offset) {
        record.copy_positions.resize(copies.size());
        Bounds moved = prototype_bounds;
        for (size_t copy = 0; copy < copies.size(); ++copy) {
            std::vector<float>& positions = record.copy_positions[copy];
            positions = record.positions;
            for (size_t vertex = 0; vertex < mesh.vertices.size(); ++vertex) {
                const glm::vec3 offset = vertex_offset(uint32_t(copy), uint32_t(vertex));
                for (int axis = 0; axis < 3; ++axis) positions[3 * vertex + size_t(axis)] += offset[axis];
                moved.extend(glm::vec3(positions[3 * vertex], positions[3 * vertex + 1], positions[3 * vertex + 2]));
            }
        }
        prototype_bounds = moved;
    }
    record.copy_models.reserve(copies.size());
    record.copy_normal_matrices.reserve(copies.size());
    for (size_t copy = 0; copy < copies.size(); ++copy) {
        const glm::mat4& model = copies[copy].model;
        const float determinant = glm::determinant(glm::mat3(model));
        if (!is_finite(model) || !std::isfinite(determinant)) throw reject(copy, "its transform is not finite");
        if (std::abs(determinant) < 1e-12f) throw reject(copy, "its transform is degenerate (a zero scale flattens it)");
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 local((corner & 1) ? prototype_bounds.max.x : prototype_bounds.min.x,
                                  (corner & 2) ? prototype_bounds.max.y : prototype_bounds.min.y,
                                  (corner & 4) ? prototype_bounds.max.z : prototype_bounds.min.z);
            const glm::vec3 world = glm::vec3(model * glm::vec4(local, 1.0f));
            if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z))
                throw reject(copy, "a vertex position is not finite");
            bounds_.extend(world);
        }
        record.copy_models.push_back(model);
        record.copy_normal_matrices.emplace_back(copies[copy].normal_matrix[0], copies[copy].normal_matrix[1],
                                                 copies[copy].normal_matrix[2]);
    }
    triangle_count_ += copies.size() * triangles;
    stored_triangle_count_ += record.copy_positions.empty() ? triangles : copies.size() * triangles;
    records_.push_back(std::move(record));
}

void EmbreeScene::build_embree_scenes(const std::string& device_config) {
    device_ = rtcNewDevice(device_config.empty() ? nullptr : device_config.c_str());
    if (!device_)
        throw std::runtime_error(fmt::format("Embree: cannot create a device{}: {}",
                                             device_config.empty() ? "" : " with config '" + device_config + "'",
                                             embree_error_name(rtcGetDeviceError(nullptr))));
    bool every_geometry_casts = true;
    for (const Record& record : records_) every_geometry_casts = every_geometry_casts && record.casts_shadows;

    visible_scene_ = rtcNewScene(device_);
    shadow_scene_ = every_geometry_casts ? visible_scene_ : rtcNewScene(device_);
    if (every_geometry_casts) rtcRetainScene(visible_scene_);
    for (RTCScene target : {visible_scene_, shadow_scene_}) {
        rtcSetSceneBuildQuality(target, RTC_BUILD_QUALITY_HIGH);
        rtcSetSceneFlags(target, RTC_SCENE_FLAG_NONE);
    }
    // Instance IDs follow the records' IDs, each population's copies in a row.
    first_instance_id_ = unsigned(records_.size());
    unsigned next_instance = first_instance_id_;
    for (Record& record : records_) {
        if (!record.instanced()) continue;
        record.first_instance = next_instance;
        next_instance += unsigned(record.copy_models.size());
    }
    instance_owner_.reserve(next_instance - first_instance_id_);
    for (size_t geom_id = 0; geom_id < records_.size(); ++geom_id) {
        const Record& record = records_[geom_id];
        if (record.instanced()) {
            const CopyFilter* filter = nullptr;
            if (record.copy_alpha_test >= 0) {
                copy_filters_.push_back({&copy_alpha_tests_[size_t(record.copy_alpha_test)], record.first_instance});
                filter = &copy_filters_.back();
            }
            // One prototype scene for every copy, or, for copies with their own positions, one each.
            const size_t scenes = record.copy_positions.empty() ? 1 : record.copy_positions.size();
            for (size_t scene_index = 0; scene_index < scenes; ++scene_index) {
                RTCScene prototype = rtcNewScene(device_);
                prototype_scenes_.push_back(prototype);
                rtcSetSceneBuildQuality(prototype, RTC_BUILD_QUALITY_HIGH);
                RTCGeometry geometry = create_geometry(
                    record, nullptr, filter, record.copy_positions.empty() ? nullptr : &record.copy_positions[scene_index]);
                rtcAttachGeometryByID(prototype, geometry, 0);
                rtcReleaseGeometry(geometry);
                rtcCommitScene(prototype);
                if (record.copy_positions.empty())
                    attach_copies(record, prototype, 0, record.copy_models.size());
                else
                    attach_copies(record, prototype, scene_index, 1);
            }
            instance_owner_.insert(instance_owner_.end(), record.copy_models.size(), unsigned(geom_id));
            continue;
        }
        const AlphaTest* alpha_test = record.alpha_test >= 0 ? &alpha_tests_[size_t(record.alpha_test)] : nullptr;
        RTCGeometry visible = create_geometry(record, alpha_test, nullptr);
        rtcAttachGeometryByID(visible_scene_, visible, unsigned(geom_id));
        rtcReleaseGeometry(visible);
        if (!every_geometry_casts && record.casts_shadows) {
            RTCGeometry shadow = create_geometry(record, alpha_test, nullptr);
            rtcAttachGeometryByID(shadow_scene_, shadow, unsigned(geom_id));
            rtcReleaseGeometry(shadow);
        }
    }
    throw_if_embree_failed(device_, "creating geometry");
    rtcCommitScene(visible_scene_);
    if (!every_geometry_casts) rtcCommitScene(shadow_scene_);
    throw_if_embree_failed(device_, "building the BVH");
}

// One instance of `prototype` per copy, in the visible scene and, when the population casts
// shadows, in a separate shadow scene under the same ID.
void EmbreeScene::attach_copies(const Record& record, RTCScene prototype, size_t first, size_t count) {
    std::vector<RTCScene> targets{visible_scene_};
    if (shadow_scene_ != visible_scene_ && record.casts_shadows) targets.push_back(shadow_scene_);
    for (size_t copy = first; copy < first + count; ++copy) {
        for (RTCScene target : targets) {
            RTCGeometry instance = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(instance, prototype);
            rtcSetGeometryTimeStepCount(instance, 1);
            rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &record.copy_models[copy][0][0]);
            rtcCommitGeometry(instance);
            rtcAttachGeometryByID(target, instance, record.first_instance + unsigned(copy));
            rtcReleaseGeometry(instance);
        }
    }
}

RTCGeometry EmbreeScene::create_geometry(const Record& record, const AlphaTest* alpha_test,
                                         const CopyFilter* copy_filter, const std::vector<float>* positions) const {
    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    const size_t vertex_count = record.normals.size();
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               (positions ? *positions : record.positions).data(), 0,
                               3 * sizeof(float), vertex_count);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, record.indices->data(), 0,
                               3 * sizeof(uint32_t), record.indices->size() / 3);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    if (alpha_test) {
        rtcSetGeometryUserData(geometry, const_cast<AlphaTest*>(alpha_test));
        rtcSetGeometryIntersectFilterFunction(geometry, alpha_test_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, alpha_test_filter);
    } else if (copy_filter) {
        rtcSetGeometryUserData(geometry, const_cast<CopyFilter*>(copy_filter));
        rtcSetGeometryIntersectFilterFunction(geometry, copy_alpha_test_filter);
        rtcSetGeometryOccludedFilterFunction(geometry, copy_alpha_test_filter);
    }
    rtcCommitGeometry(geometry);
    return geometry;
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::release() {
    if (shadow_scene_) rtcReleaseScene(shadow_scene_);
    if (visible_scene_) rtcReleaseScene(visible_scene_);
    for (RTCScene prototype : prototype_scenes_) rtcReleaseScene(prototype);
    prototype_scenes_.clear();
    if (device_) rtcReleaseDevice(device_);
    shadow_scene_ = visible_scene_ = nullptr;
    device_ = nullptr;
}

EmbreeHit EmbreeScene::resolve(const RTCHit& hit) const {
    EmbreeHit resolved;
    resolved.geometric_normal = glm::vec3(hit.Ng_x, hit.Ng_y, hit.Ng_z);
    if (hit.instID[0] == RTC_INVALID_GEOMETRY_ID) {
        resolved.geometry = hit.geomID;
        resolved.primitive = hit.primID;
        return resolved;
    }
    // Embree reports an instanced hit's Ng in the prototype's space.
    const unsigned owner = instance_owner_[hit.instID[0] - first_instance_id_];
    const Record& record = records_[owner];
    const uint32_t copy = hit.instID[0] - record.first_instance;
    resolved.geometry = owner;
    resolved.primitive = uint64_t(copy) * record.instance.prototype_triangles + hit.primID;
    resolved.geometric_normal = record.copy_normal_matrices[copy] * resolved.geometric_normal;
    return resolved;
}

glm::vec3 EmbreeScene::albedo(unsigned geom_id, uint64_t prim_id, float u, float v) const {
    const Record& record = records_[geom_id];
    if (!record.albedo_scale) return record.material.albedo;
    const uint32_t triangles = record.instance.prototype_triangles;
    return record.material.albedo * record.albedo_scale(uint32_t(prim_id / triangles), uint32_t(prim_id % triangles), u, v);
}

glm::vec3 EmbreeScene::shading_normal(unsigned geom_id, uint64_t prim_id, float u, float v) const {
    const Record& record = records_[geom_id];
    uint64_t triangle_index = prim_id;
    const glm::mat3* to_world = nullptr;
    if (record.instanced()) {
        const uint32_t triangles = record.instance.prototype_triangles;
        triangle_index = prim_id % triangles;
        to_world = &record.copy_normal_matrices[size_t(prim_id / triangles)];
    }
    const uint32_t* triangle = record.indices->data() + size_t(triangle_index) * 3;
    glm::vec3 normal = (1.0f - u - v) * record.normals[triangle[0]] + u * record.normals[triangle[1]] +
                       v * record.normals[triangle[2]];
    if (to_world) normal = *to_world * normal;
    const float length = glm::length(normal);
    return length > 0.0f ? normal / length : glm::vec3(0.0f);
}

}  // namespace canopy
