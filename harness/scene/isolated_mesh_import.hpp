// import_mesh_file in a child process. Debian's assimp is not ours to fix, and some files crash
// it; in a child, such a crash becomes a MeshFileError ("assimp crashed while reading FILE
// (signal N)") instead of taking canopy down with it or corrupting its heap.
#pragma once

#include "scene/mesh_import.hpp"

namespace canopy {

// Forks, imports `file` in the child, and passes the mesh (or the child's MeshFileError) back
// through an anonymous shared-memory file. What comes back is checked again (mesh_defect). A
// child still reading after CANOPY_MESH_IMPORT_TIMEOUT seconds (default 300; some files make
// assimp loop forever) is killed and reported as a MeshFileError.
// Test hook: with CANOPY_TEST_MESH_IMPORT_SIGNAL=N in the environment, the child raises signal N
// instead of importing, so tests can check how a crash is reported.
TriangleMesh import_mesh_file_isolated(const std::filesystem::path& file);

}  // namespace canopy
