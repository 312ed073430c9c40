// Model files (glTF/GLB, OBJ, PLY, ...) read with assimp into one triangle mesh, and the checks
// canopy applies to whatever assimp returns: assimp is a large parser that is not ours, so its
// output is validated before a single index is used.
#pragma once

#include "scene/geometry.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace canopy {

// Why a mesh file cannot be used. The caller names the [[object]] (file:line) it belongs to.
class MeshFileError : public std::runtime_error {
public:
    MeshFileError(const std::string& message, std::string hint)
        : std::runtime_error(message), hint_(std::move(hint)) {}
    const std::string& hint() const { return hint_; }

private:
    std::string hint_;
};

// Reads `file` with assimp in this process: its own structure validation first, then canopy's
// checks, then triangulation and normals. Throws MeshFileError; a crash inside assimp itself is
// not caught (see import_mesh_file_isolated).
TriangleMesh import_mesh_file(const std::filesystem::path& file);

// What is wrong with a mesh, or nothing: no triangles, an index past the vertices, a non-finite
// position or a normal that is not unit length.
std::optional<std::string> mesh_defect(const TriangleMesh& mesh);

}  // namespace canopy
