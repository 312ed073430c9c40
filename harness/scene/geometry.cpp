#include "scene/geometry.hpp"

#include "core/error.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

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

bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

TriangleMesh load_mesh_file(const Object& object) {
    const std::filesystem::path& file = object.mesh_file;
    const auto error = [&](const std::string& message, const std::string& hint) {
        return ConfigError(object.where.file, object.where.line,
                           fmt::format("object '{}': {}", object.name, message), hint);
    };
    std::error_code ignored;
    if (!std::filesystem::is_regular_file(file, ignored))
        throw error(fmt::format("mesh file '{}' does not exist", file.string()),
                    "`file` is resolved relative to the scene config's folder");

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(file.string(), aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                                                aiProcess_PreTransformVertices |
                                                                aiProcess_JoinIdenticalVertices);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode)
        throw error(fmt::format("cannot read mesh file '{}': {}", file.string(), importer.GetErrorString()),
                    "assimp reads glTF/GLB, OBJ, PLY, FBX, STL and more; check that the file is complete");

    TriangleMesh merged;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;  // points and lines
        const uint32_t base = uint32_t(merged.vertices.size());
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            glm::vec3 normal(0.0f);
            if (mesh->HasNormals()) normal = glm::vec3(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z);
            const glm::vec3 position(p.x, p.y, p.z);
            if (!is_finite(position))
                throw error(fmt::format("mesh file '{}' has a vertex with a non-finite position", file.string()),
                            "repair or re-export the model");
            merged.vertices.push_back({position, normal});
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            add_triangle(merged, base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]);
        }
    }
    if (merged.triangle_count() == 0)
        throw error(fmt::format("mesh file '{}' contains no triangles", file.string()),
                    "point clouds and line sets cannot be rendered; use a model with faces");

    // Some files carry zero or non-finite normals; fall back to the area-weighted face normals.
    std::vector<glm::vec3> face_normal_sum(merged.vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t < merged.indices.size(); t += 3) {
        const uint32_t a = merged.indices[t], b = merged.indices[t + 1], c = merged.indices[t + 2];
        const glm::vec3 n = glm::cross(merged.vertices[b].position - merged.vertices[a].position,
                                       merged.vertices[c].position - merged.vertices[a].position);
        for (uint32_t i : {a, b, c}) face_normal_sum[i] += n;
    }
    for (size_t i = 0; i < merged.vertices.size(); ++i) {
        glm::vec3& normal = merged.vertices[i].normal;
        const float length = glm::length(normal);
        if (std::isfinite(length) && length > 1e-12f) {
            normal /= length;
        } else {
            const float fallback_length = glm::length(face_normal_sum[i]);
            normal = fallback_length > 0.0f ? face_normal_sum[i] / fallback_length : glm::vec3(0, 1, 0);
        }
    }
    return merged;
}

}  // namespace

TriangleMesh build_object_mesh(const Object& object) {
    switch (object.shape) {
        case ShapeType::plane: return build_plane(object.plane_size);
        case ShapeType::box: return build_box(object.box_size);
        case ShapeType::sphere: return build_sphere(object.radius, std::max(3, object.segments));
        case ShapeType::cylinder: return build_cylinder(object.radius, object.height, std::max(3, object.segments));
        case ShapeType::mesh: return load_mesh_file(object);
    }
    throw std::logic_error("unhandled ShapeType");
}

std::vector<TriangleMesh> build_scene_meshes(const Scene& scene) {
    std::vector<TriangleMesh> meshes;
    meshes.reserve(scene.objects.size());
    for (const Object& object : scene.objects) meshes.push_back(build_object_mesh(object));
    return meshes;
}

Bounds scene_bounds(const Scene& scene, const std::vector<TriangleMesh>& meshes) {
    if (meshes.size() != scene.objects.size())
        throw std::logic_error("scene_bounds: one mesh per scene object expected");
    Bounds bounds;
    for (size_t i = 0; i < meshes.size(); ++i) {
        for (const Transform& instance : scene.objects[i].instances) {
            const glm::mat4 matrix = instance.matrix();
            for (const Vertex& vertex : meshes[i].vertices)
                bounds.extend(glm::vec3(matrix * glm::vec4(vertex.position, 1.0f)));
        }
    }
    return bounds;
}

}  // namespace canopy
