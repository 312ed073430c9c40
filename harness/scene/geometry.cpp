#include "scene/geometry.hpp"

#include "scene/height_field.hpp"

#include "scene/population_kind.hpp"

#include "core/error.hpp"
#include "scene/isolated_mesh_import.hpp"
#include "scene/scene_limits.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace canopy {

void Bounds::extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
}

float Bounds::radius() const { return empty() ? 0.0f : 0.5f * glm::length(max - min); }

namespace {

constexpr float kPi = 3.14159265358979323846f;

uint32_t add_vertex(TriangleMesh& mesh, const glm::vec3& position, const glm::vec3& normal) {
    mesh.vertices.push_back({position, normal});
    return uint32_t(mesh.vertices.size() - 1);
}

void add_triangle(TriangleMesh& mesh, uint32_t a, uint32_t b, uint32_t c) {
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
}

// A flat quad centred at `center` spanning +-u and +-v; u x v must point along the outward normal
// so that the two triangles wind counter-clockwise seen from outside.
void add_quad(TriangleMesh& mesh, const glm::vec3& center, const glm::vec3& u, const glm::vec3& v) {
    const glm::vec3 normal = glm::normalize(glm::cross(u, v));
    const uint32_t first = add_vertex(mesh, center - u - v, normal);
    add_vertex(mesh, center + u - v, normal);
    add_vertex(mesh, center + u + v, normal);
    add_vertex(mesh, center - u + v, normal);
    add_triangle(mesh, first, first + 1, first + 2);
    add_triangle(mesh, first, first + 2, first + 3);
}

TriangleMesh build_plane(const glm::vec2& size) {
    TriangleMesh mesh;
    // u = +z, v = +x: z x x = +y.
    add_quad(mesh, glm::vec3(0.0f), glm::vec3(0, 0, 0.5f * size.y), glm::vec3(0.5f * size.x, 0, 0));
    return mesh;
}

TriangleMesh build_box(const glm::vec3& size) {
    const glm::vec3 half = 0.5f * size;
    const glm::vec3 x(half.x, 0, 0), y(0, half.y, 0), z(0, 0, half.z);
    TriangleMesh mesh;
    add_quad(mesh, x, y, z);    // +x: y x z = +x
    add_quad(mesh, -x, z, y);   // -x
    add_quad(mesh, y, z, x);    // +y
    add_quad(mesh, -y, x, z);   // -y
    add_quad(mesh, z, x, y);    // +z
    add_quad(mesh, -z, y, x);   // -z
    return mesh;
}

// Latitude rings from the +y pole (ring 0) to the -y pole; the seam column is duplicated so
// every ring has segments + 1 vertices.
TriangleMesh build_sphere(float radius, int segments) {
    const int rings = std::max(2, segments / 2);
    TriangleMesh mesh;
    for (int ring = 0; ring <= rings; ++ring) {
        const float theta = kPi * float(ring) / float(rings);
        for (int segment = 0; segment <= segments; ++segment) {
            const float phi = 2.0f * kPi * float(segment) / float(segments);
            const glm::vec3 normal(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
            add_vertex(mesh, radius * normal, normal);
        }
    }
    const auto index = [&](int ring, int segment) { return uint32_t(ring * (segments + 1) + segment); };
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            const uint32_t upper = index(ring, segment), lower = index(ring + 1, segment);
            const uint32_t lower_next = index(ring + 1, segment + 1), upper_next = index(ring, segment + 1);
            // Skip the triangle that would collapse onto a pole.
            if (ring != rings - 1) add_triangle(mesh, upper, lower_next, lower);
            if (ring != 0) add_triangle(mesh, upper, upper_next, lower_next);
        }
    }
    return mesh;
}

TriangleMesh build_cylinder(float radius, float height, int segments) {
    TriangleMesh mesh;
    const float top = 0.5f * height, bottom = -0.5f * height;
    const auto ring_direction = [&](int segment) {
        const float phi = 2.0f * kPi * float(segment) / float(segments);
        return glm::vec3(std::cos(phi), 0.0f, std::sin(phi));
    };

    // Side: smooth normals, seam duplicated.
    const uint32_t side_start = uint32_t(mesh.vertices.size());
    for (int segment = 0; segment <= segments; ++segment) {
        const glm::vec3 direction = ring_direction(segment);
        add_vertex(mesh, radius * direction + glm::vec3(0, top, 0), direction);
        add_vertex(mesh, radius * direction + glm::vec3(0, bottom, 0), direction);
    }
    for (int segment = 0; segment < segments; ++segment) {
        const uint32_t upper = side_start + 2 * segment, lower = upper + 1;
        const uint32_t upper_next = upper + 2, lower_next = upper + 3;
        add_triangle(mesh, upper, lower_next, lower);
        add_triangle(mesh, upper, upper_next, lower_next);
    }

    // Caps: flat normals, a fan around each centre.
    for (const float y : {top, bottom}) {
        const glm::vec3 normal(0, y == top ? 1.0f : -1.0f, 0);
        const uint32_t center = add_vertex(mesh, glm::vec3(0, y, 0), normal);
        for (int segment = 0; segment < segments; ++segment)
            add_vertex(mesh, radius * ring_direction(segment) + glm::vec3(0, y, 0), normal);
        for (int segment = 0; segment < segments; ++segment) {
            const uint32_t current = center + 1 + segment;
            const uint32_t next = center + 1 + (segment + 1) % segments;
            if (y == top) add_triangle(mesh, center, next, current);
            else add_triangle(mesh, center, current, next);
        }
    }
    return mesh;
}

TriangleMesh load_mesh_file(const Object& object) {
    const std::filesystem::path& file = object.mesh_file;
    const auto error = [&](const std::string& message, const std::string& hint) {
        return ConfigError(object.where.file, object.where.line,
                           fmt::format("object '{}': {}", object.name, message), hint);
    };
    std::error_code ignored;
    const auto status = std::filesystem::status(file, ignored);
    if (!std::filesystem::exists(status))
        throw error(fmt::format("mesh file '{}' does not exist", file.string()),
                    "`file` is resolved relative to the scene config's folder");
    if (std::filesystem::is_directory(status))
        throw error(fmt::format("mesh file '{}' is a directory, not a model file", file.string()),
                    "name the model file inside it");
    if (!std::filesystem::is_regular_file(status))
        throw error(fmt::format("mesh file '{}' is not a regular file", file.string()),
                    "name a model file (glTF/GLB, OBJ, PLY, ...), not a device, pipe or socket");
    try {
        return import_mesh_file_isolated(file);
    } catch (const MeshFileError& failure) {
        throw error(failure.what(), failure.hint());
    }
}

// Every world-space vertex of every instance inside the coordinate range both renderers
// compute precisely (scene_limits.hpp), checked in double so that nothing overflows on the way.
void require_in_scene(const Object& object, const TriangleMesh& mesh) {
    const double bound = limits::kMaxCoordinate;
    for (size_t instance = 0; instance < object.instances.size(); ++instance) {
        const glm::dmat4 matrix(object.instances[instance].matrix());
        for (const Vertex& vertex : mesh.vertices) {
            const glm::dvec3 world(matrix * glm::dvec4(glm::dvec3(vertex.position), 1.0));
            if (std::abs(world.x) <= bound && std::abs(world.y) <= bound && std::abs(world.z) <= bound) continue;
            throw ConfigError(object.where.file, object.where.line,
                              fmt::format("object '{}'{} reaches ({:.3g}, {:.3g}, {:.3g}), outside the scene's coordinate "
                                          "range [-{:g}, {:g}]",
                                          object.name,
                                          object.instances.size() > 1 ? fmt::format(" (instance {})", instance + 1) : "",
                                          world.x, world.y, world.z, bound, bound),
                              "canopy computes in single precision: keep every coordinate within 1e6 scene units "
                              "(configs/README.md, \"Limits\"); check the object's translate and scale, and the "
                              "model's units");
        }
    }
}

// A population's copies: within the coordinate range (bounded conservatively, by the region's
// corners and the largest copy's reach, so that a million copies cost no more than one), and
// a prototype within the triangle budget of what the reference and the GPU store once.
void require_in_scene(const Population& population, const TriangleMesh& mesh) {
    const auto error = [&](const std::string& message, const std::string& hint) {
        return ConfigError(population.where.file, population.where.line,
                           fmt::format("population '{}': {}", population.name, message), hint);
    };
    if (double(mesh.triangle_count()) > limits::kMaxPrototypeTriangles)
        throw error(fmt::format("its prototype has {} triangles, more than the {:.3g} a prototype may have",
                                mesh.triangle_count(), limits::kMaxPrototypeTriangles),
                    population.family ? "make the patch sparser (see the kind's parameters in `canopy list`)"
                                      : "use a prototype with fewer triangles (fewer 'segments')");
    if (population.family) {
        Bounds local;
        for (const Vertex& vertex : mesh.vertices) local.extend(vertex.position);
        double far = 0.0;
        for (const PopulationInstance& copy : population.family->instances)
            for (int corner = 0; corner < 8 && !local.empty(); ++corner) {
                const glm::vec3 p((corner & 1) ? local.max.x : local.min.x, (corner & 2) ? local.max.y : local.min.y,
                                  (corner & 4) ? local.max.z : local.min.z);
                const glm::dvec4 world = glm::dmat4(copy.model) * glm::dvec4(glm::dvec3(p), 1.0);
                far = std::max({far, std::abs(world.x), std::abs(world.y), std::abs(world.z)});
            }
        if (far <= limits::kMaxCoordinate) return;
        throw error(fmt::format("its copies reach {:.3g} scene units from the origin, outside the scene's coordinate "
                                "range [-{:g}, {:g}]", far, limits::kMaxCoordinate, limits::kMaxCoordinate),
                    "canopy computes in single precision: keep every coordinate within 1e6 scene units "
                    "(configs/README.md, \"Limits\")");
    }
    const glm::dmat4 own(population.prototype.instances.empty() ? glm::mat4(1.0f)
                                                               : population.prototype.instances.front().matrix());
    double reach = 0.0;  // the farthest a prototype vertex lies from the copy's origin
    for (const Vertex& vertex : mesh.vertices)
        reach = std::max(reach, glm::length(glm::dvec3(own * glm::dvec4(glm::dvec3(vertex.position), 1.0))));
    reach *= std::max(std::abs(double(population.scale_min)), std::abs(double(population.scale_max)));
    const double bound = limits::kMaxCoordinate;
    const double far_x = std::max(std::abs(double(population.region_min.x)), std::abs(double(population.region_max.x)));
    const double far_z = std::max(std::abs(double(population.region_min.y)), std::abs(double(population.region_max.y)));
    const double far_y = std::abs(double(population.ground_y));
    if (far_x + reach <= bound && far_y + reach <= bound && far_z + reach <= bound) return;
    throw error(fmt::format("its copies may reach {:.3g} scene units from the origin, outside the scene's coordinate "
                            "range [-{:g}, {:g}]",
                            std::max({far_x, far_y, far_z}) + reach, bound, bound),
                "canopy computes in single precision: keep every coordinate within 1e6 scene units "
                "(configs/README.md, \"Limits\"); check the region, ground, scale and the prototype's size");
}

}  // namespace

TriangleMesh build_object_mesh(const Object& object) {
    switch (object.shape) {
        case ShapeType::plane: return build_plane(object.plane_size);
        case ShapeType::box: return build_box(object.box_size);
        case ShapeType::sphere: return build_sphere(object.radius, std::max(3, object.segments));
        case ShapeType::cylinder: return build_cylinder(object.radius, object.height, std::max(3, object.segments));
        case ShapeType::mesh: return load_mesh_file(object);
        case ShapeType::heightfield: return build_height_field_mesh(*object.height_field);
    }
    throw std::logic_error("unhandled ShapeType");
}

std::vector<TriangleMesh> build_scene_meshes(const Scene& scene) {
    std::vector<TriangleMesh> meshes;
    meshes.reserve(scene.objects.size() + scene.populations.size());
    for (const Object& object : scene.objects) {
        meshes.push_back(build_object_mesh(object));
        require_in_scene(object, meshes.back());
    }
    for (const Population& population : scene.populations) {
        meshes.push_back(population.family ? population.family->prototype : build_object_mesh(population.prototype));
        require_in_scene(population, meshes.back());
    }
    return meshes;
}

const TriangleMesh& prototype_mesh(const Scene& scene, const std::vector<TriangleMesh>& meshes, size_t index) {
    if (meshes.size() != scene.objects.size() + scene.populations.size() || index >= scene.populations.size())
        throw std::logic_error(fmt::format("prototype_mesh: population {} of {}, with {} meshes for {} objects",
                                           index, scene.populations.size(), meshes.size(), scene.objects.size()));
    return meshes[scene.objects.size() + index];
}

Bounds scene_bounds(const Scene& scene, const std::vector<TriangleMesh>& meshes) {
    if (meshes.size() != scene.objects.size() + scene.populations.size())
        throw std::logic_error("scene_bounds: one mesh per scene object and population expected");
    Bounds bounds;
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        for (const Transform& instance : scene.objects[i].instances) {
            const glm::mat4 matrix = instance.matrix();
            for (const Vertex& vertex : meshes[i].vertices)
                bounds.extend(glm::vec3(matrix * glm::vec4(vertex.position, 1.0f)));
        }
    }
    // A population's copies by the corners of the prototype's box: exact for copies that are
    // moved, scaled or mirrored (a grass field's cells), a little loose for rotated ones, and
    // O(copies) for a field of 200,000 cells of 60,000 vertices each.
    for (size_t p = 0; p < scene.populations.size(); ++p) {
        Bounds prototype;
        for (const Vertex& vertex : prototype_mesh(scene, meshes, p).vertices) prototype.extend(vertex.position);
        if (prototype.empty()) continue;
        const auto copies = generate_instances(scene.populations[p]);
        for (const PopulationInstance& instance : *copies)
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 local((corner & 1) ? prototype.max.x : prototype.min.x,
                                      (corner & 2) ? prototype.max.y : prototype.min.y,
                                      (corner & 4) ? prototype.max.z : prototype.min.z);
                bounds.extend(glm::vec3(instance.model * glm::vec4(local, 1.0f)));
            }
    }
    return bounds;
}

}  // namespace canopy
