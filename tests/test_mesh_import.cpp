// Mesh files that are malformed or crash assimp: canopy validates what assimp returns, reads
// files in a child process, and reports either as a ConfigError at the [[object]]'s line.
#include "core/error.hpp"
#include "scene/geometry.hpp"
#include "scene/isolated_mesh_import.hpp"
#include "scene/mesh_import.hpp"
#include "support/config_error_of.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <optional>
#include <string>

using namespace canopy;
using test::contains;

namespace {

const std::filesystem::path kMeshes = std::filesystem::path(CANOPY_TEST_DATA) / "bad_input/meshes";
const std::filesystem::path kAssimpModels = "/usr/share/assimp/models";

Object mesh_object(const std::filesystem::path& file) {
    Object object;
    object.shape = ShapeType::mesh;
    object.name = "model";
    object.mesh_file = file;
    object.where = {"scene.toml", 7};
    return object;
}

std::optional<ConfigError> load_error(const std::filesystem::path& file) {
    return test::config_error_of([&] { build_object_mesh(mesh_object(file)); });
}

// Sets an environment variable for one scope.
struct ScopedEnvironment {
    std::string name;
    ScopedEnvironment(std::string variable, const std::string& value) : name(std::move(variable)) {
        setenv(name.c_str(), value.c_str(), 1);
    }
    ~ScopedEnvironment() { unsetenv(name.c_str()); }
};

TriangleMesh triangle() {
    TriangleMesh mesh;
    mesh.vertices = {{{0, 0, 0}, {0, 0, 1}}, {{1, 0, 0}, {0, 0, 1}}, {{0, 1, 0}, {0, 0, 1}}};
    mesh.indices = {0, 1, 2};
    return mesh;
}

}  // namespace

TEST_CASE("a PLY face index past the vertices is refused with the file and the reason") {
    // Before: heap corruption inside assimp's post-processing (free(): invalid next size).
    const auto error = load_error(kMeshes / "face_index_out_of_range.ply");
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(error->file() == "scene.toml");
    CHECK(error->line() == 7);
    CHECK(contains(error->what(), "face_index_out_of_range.ply"));
    CHECK(contains(error->what(), "out of range"));
}

TEST_CASE("non-finite vertex positions that assimp accepts are refused by canopy's own checks") {
    const auto error = load_error(kMeshes / "nan_vertex.obj");
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(error->line() == 7);
    CHECK(contains(error->what(), "nan_vertex.obj"));
    CHECK(contains(error->what(), "non-finite position"));
}

TEST_CASE("a mesh path that is a directory says so") {
    const auto error = load_error(kMeshes / "a_folder.obj");
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(contains(error->what(), "is a directory"));
    CHECK(!contains(error->what(), "not exist"));
}

TEST_CASE("mesh_defect finds every kind of broken mesh") {
    CHECK(!mesh_defect(triangle()));
    TriangleMesh empty;
    CHECK(mesh_defect(empty));
    TriangleMesh ragged = triangle();
    ragged.indices.push_back(0);
    CHECK(mesh_defect(ragged));
    TriangleMesh out_of_range = triangle();
    out_of_range.indices[2] = 3;
    CHECK(mesh_defect(out_of_range));
    TriangleMesh not_finite = triangle();
    not_finite.vertices[1].position.y = std::numeric_limits<float>::infinity();
    CHECK(mesh_defect(not_finite));
    TriangleMesh bad_normal = triangle();
    bad_normal.vertices[0].normal = glm::vec3(0.0f);
    CHECK(mesh_defect(bad_normal));
}

TEST_CASE("a crash inside the mesh reader becomes a ConfigError naming the file and the signal") {
    const std::filesystem::path model = kAssimpModels / "OBJ/box.obj";
    REQUIRE(std::filesystem::exists(model));
    for (const int signal_number : {SIGSEGV, SIGABRT}) {
        CAPTURE(signal_number);
        const ScopedEnvironment crash("CANOPY_TEST_MESH_IMPORT_SIGNAL", std::to_string(signal_number));
        const auto error = load_error(model);
        REQUIRE(error);
        INFO(error->formatted());
        CHECK(error->file() == "scene.toml");
        CHECK(error->line() == 7);
        CHECK(contains(error->what(), "assimp crashed while reading"));
        CHECK(contains(error->what(), "box.obj"));
        CHECK(contains(error->what(), "signal " + std::to_string(signal_number)));
    }
    // The hook is gone with the variable: the same file loads.
    CHECK(build_object_mesh(mesh_object(model)).triangle_count() > 0);
}

TEST_CASE("an error raised in the child process arrives whole") {
    try {
        import_mesh_file_isolated(kMeshes / "nan_vertex.obj");
        FAIL("expected a MeshFileError");
    } catch (const MeshFileError& error) {
        CHECK(contains(error.what(), "non-finite position"));
        CHECK(!error.hint().empty());
    }
}

TEST_CASE("the child process returns exactly the mesh an in-process import gives") {
    for (const char* name : {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                             "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", "PLY/cube.ply", "OBJ/spider.obj"}) {
        const std::filesystem::path file = kAssimpModels / name;
        CAPTURE(file);
        REQUIRE(std::filesystem::exists(file));
        const auto start = std::chrono::steady_clock::now();
        const TriangleMesh direct = import_mesh_file(file);
        const auto middle = std::chrono::steady_clock::now();
        const TriangleMesh isolated = import_mesh_file_isolated(file);
        const auto end = std::chrono::steady_clock::now();
        MESSAGE(std::string(name) << ": " << direct.triangle_count() << " triangles, in process "
                     << std::chrono::duration<double, std::milli>(middle - start).count() << " ms, in a child "
                     << std::chrono::duration<double, std::milli>(end - middle).count() << " ms");
        REQUIRE(isolated.vertices.size() == direct.vertices.size());
        REQUIRE(isolated.indices == direct.indices);
        bool same = true;
        for (size_t i = 0; i < direct.vertices.size(); ++i)
            same = same && direct.vertices[i].position == isolated.vertices[i].position &&
                   direct.vertices[i].normal == isolated.vertices[i].normal;
        CHECK(same);
        CHECK(!mesh_defect(isolated));
    }
}

TEST_CASE("a mesh reader that never finishes is stopped after the time limit") {
    const ScopedEnvironment limit("CANOPY_MESH_IMPORT_TIMEOUT", "1");
    SUBCASE("a child that hangs (stopped by the test hook)") {
        const ScopedEnvironment stop("CANOPY_TEST_MESH_IMPORT_SIGNAL", std::to_string(SIGSTOP));
        const auto start = std::chrono::steady_clock::now();
        const auto error = load_error(kAssimpModels / "OBJ/box.obj");
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        REQUIRE(error);
        INFO(error->formatted());
        CHECK(error->line() == 7);
        CHECK(contains(error->what(), "did not finish reading"));
        CHECK(contains(error->hint(), "CANOPY_MESH_IMPORT_TIMEOUT"));
        CHECK(seconds < 30.0);
    }
    SUBCASE("a PLY header that makes Debian's assimp 5.2.5 loop (found by fuzz_mesh)") {
        // Whatever a future assimp makes of it, canopy must come back with a clean error.
        const auto error = load_error(kMeshes / "assimp_loops_forever.ply");
        REQUIRE(error);
        INFO(error->formatted());
        CHECK(error->line() == 7);
    }
}
