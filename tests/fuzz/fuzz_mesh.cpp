// libFuzzer target: mesh files through canopy's loader (assimp, then canopy's checks). The
// first byte of an input picks the format (its value modulo 4: OBJ, PLY, glTF, GLB); the rest
// is the file, written to a scratch folder as model.<ext>. A MeshFileError is a clean
// rejection; a mesh that loads must pass mesh_defect. The import runs in this process, so that
// the sanitizers see canopy's code; canopy itself reads files in a child process
// (scene/isolated_mesh_import.hpp), which turns crashes inside assimp into errors. Such crashes
// stop this target: fuzz with -fork=1 -ignore_crashes=1 (tests/fuzz/README.md).
#include "scene/mesh_import.hpp"
#include "scratch_folder.hpp"

#include <array>
#include <cstdint>
#include <string_view>

using namespace canopy;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const fuzz::ScratchFolder folder("canopy-fuzz-mesh");
    static constexpr std::array<const char*, 4> kExtensions{".obj", ".ply", ".gltf", ".glb"};
    if (size < 1) return 0;
    const std::string name = std::string("model") + kExtensions[data[0] % kExtensions.size()];
    const std::filesystem::path file =
        folder.write(name, std::string_view(reinterpret_cast<const char*>(data + 1), size - 1));
    try {
        const TriangleMesh mesh = import_mesh_file(file);
        if (const auto defect = mesh_defect(mesh)) fuzz::property_violated("a defective mesh loaded: " + *defect);
    } catch (const MeshFileError&) {
    }
    std::filesystem::remove(file);
    return 0;
}
