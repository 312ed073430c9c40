#include "scene/mesh_import.hpp"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <fmt/format.h>

#include <cmath>
#include <cstdint>
#include <limits>

namespace canopy {

namespace {

const char* const kRepairHint = "repair or re-export the model (e.g. with Blender or meshlab)";

bool is_finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool is_finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Checks one of assimp's meshes before anything reads through its indices: the arrays its
// counts promise exist, and every face index names one of its vertices.
void check_assimp_mesh(const aiMesh* mesh, unsigned mesh_index, const std::string& file) {
    const auto defect = [&](const std::string& what) {
        return MeshFileError(fmt::format("mesh file '{}' is malformed: mesh {} {}", file, mesh_index, what), kRepairHint);
    };
    if (!mesh) throw defect("is missing");
    if (mesh->mNumVertices > 0 && !mesh->mVertices) throw defect("has a vertex count but no vertices");
    if (mesh->mNumFaces > 0 && !mesh->mFaces) throw defect("has a face count but no faces");
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
        const aiFace& face = mesh->mFaces[f];
        // assimp's triangulation asserts (and aborts) on a face without indices.
        if (face.mNumIndices == 0 || !face.mIndices) throw defect(fmt::format("face {} has no indices", f));
        for (unsigned k = 0; k < face.mNumIndices; ++k)
            if (face.mIndices[k] >= mesh->mNumVertices)
                throw defect(fmt::format("face {} uses vertex {}, out of range: the mesh has {} vertices", f, face.mIndices[k],
                                         mesh->mNumVertices));
    }
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
        if (!is_finite(mesh->mVertices[v]))
            throw defect(fmt::format("vertex {} has a non-finite position", v));
}

void check_assimp_scene(const aiScene* scene, const std::string& file) {
    if (scene->mNumMeshes > 0 && !scene->mMeshes)
        throw MeshFileError(fmt::format("mesh file '{}' is malformed: it counts meshes but has none", file), kRepairHint);
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) check_assimp_mesh(scene->mMeshes[m], m, file);
}

// Every triangle of every mesh of a pre-transformed scene, in one vertex and index list.
TriangleMesh merge_triangles(const aiScene* scene, const std::string& file) {
    TriangleMesh merged;
    for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
        const aiMesh* mesh = scene->mMeshes[m];
        if (!(mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) continue;  // points and lines
        if (merged.vertices.size() + mesh->mNumVertices > std::numeric_limits<uint32_t>::max())
            throw MeshFileError(fmt::format("mesh file '{}' has more than 2^32 vertices", file),
                                "canopy indexes vertices with 32 bits; split or decimate the model");
        const uint32_t base = uint32_t(merged.vertices.size());
        const bool normals = mesh->HasNormals();
        for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
            const aiVector3D& p = mesh->mVertices[v];
            const glm::vec3 normal = normals ? glm::vec3(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z)
                                             : glm::vec3(0.0f);
            merged.vertices.push_back({glm::vec3(p.x, p.y, p.z), normal});
        }
        for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
            const aiFace& face = mesh->mFaces[f];
            if (face.mNumIndices != 3) continue;
            merged.indices.insert(merged.indices.end(),
                                  {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
        }
    }
    return merged;
}

// Zero or non-finite normals (some files carry them) become the area-weighted face normals.
void repair_normals(TriangleMesh& mesh) {
    std::vector<glm::vec3> face_normal_sum(mesh.vertices.size(), glm::vec3(0.0f));
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const glm::vec3 n = glm::cross(mesh.vertices[b].position - mesh.vertices[a].position,
                                       mesh.vertices[c].position - mesh.vertices[a].position);
        if (is_finite(n))
            for (uint32_t i : {a, b, c}) face_normal_sum[i] += n;
    }
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        glm::vec3& normal = mesh.vertices[i].normal;
        const float length = glm::length(normal);
        if (std::isfinite(length) && length > 1e-12f) {
            normal /= length;
            continue;
        }
        const float fallback_length = glm::length(face_normal_sum[i]);
        normal = std::isfinite(fallback_length) && fallback_length > 0.0f ? face_normal_sum[i] / fallback_length
                                                                           : glm::vec3(0, 1, 0);
    }
}

}  // namespace

std::optional<std::string> mesh_defect(const TriangleMesh& mesh) {
    if (mesh.indices.empty()) return std::string("it contains no triangles");
    if (mesh.indices.size() % 3 != 0)
        return fmt::format("its index count {} is not a multiple of 3", mesh.indices.size());
    for (size_t i = 0; i < mesh.indices.size(); ++i)
        if (mesh.indices[i] >= mesh.vertices.size())
            return fmt::format("index {} names vertex {}, but there are {} vertices", i, mesh.indices[i],
                               mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (!is_finite(mesh.vertices[v].position)) return fmt::format("vertex {} has a non-finite position", v);
        const float length = glm::length(mesh.vertices[v].normal);
        if (!(std::abs(length - 1.0f) < 1e-3f)) return fmt::format("vertex {} has a normal of length {}", v, length);
    }
    return std::nullopt;
}

TriangleMesh import_mesh_file(const std::filesystem::path& path) {
    const std::string file = path.string();
    Assimp::Importer importer;
    // Validation runs before any post-processing step: those trust the indices they are given
    // (an out-of-range PLY face index corrupted the heap inside JoinIdenticalVertices).
    const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
    if (!scene || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) || !scene->mRootNode) {
        const std::string reason = scene ? "the file is incomplete (no geometry)" : importer.GetErrorString();
        const bool invalid = reason.rfind("Validation failed", 0) == 0;  // read, but inconsistent
        throw MeshFileError(fmt::format("cannot read mesh file '{}': {}", file, reason),
                            invalid ? kRepairHint
                                    : "assimp reads glTF/GLB, OBJ, PLY, FBX, STL and more; check that the file is complete");
    }
    check_assimp_scene(scene, file);

    scene = importer.ApplyPostProcessing(aiProcess_Triangulate | aiProcess_GenSmoothNormals |
                                         aiProcess_PreTransformVertices | aiProcess_JoinIdenticalVertices);
    if (!scene)
        throw MeshFileError(fmt::format("cannot process mesh file '{}': {}", file, importer.GetErrorString()), kRepairHint);
    check_assimp_scene(scene, file);  // post-processing is assimp's code too

    TriangleMesh mesh = merge_triangles(scene, file);
    if (mesh.indices.empty())
        throw MeshFileError(fmt::format("mesh file '{}' contains no triangles", file),
                            "point clouds and line sets cannot be rendered; use a model with faces");
    repair_normals(mesh);
    if (const auto defect = mesh_defect(mesh))
        throw MeshFileError(fmt::format("mesh file '{}' cannot be used: {}", file, *defect), kRepairHint);
    return mesh;
}

}  // namespace canopy
