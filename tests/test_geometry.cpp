// Tessellated primitives, mesh files, transforms and bounds: the triangles that both the
// rasteriser and the ray tracer draw.
#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "scene/geometry.hpp"

#include <doctest/doctest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <fstream>
#include <optional>

using namespace canopy;

namespace {

const std::filesystem::path kData = std::filesystem::path(CANOPY_TEST_DATA) / "config";
const std::filesystem::path kAssimpModels = "/usr/share/assimp/models";
constexpr double kPi = 3.14159265358979323846;

glm::vec3 face_normal(const TriangleMesh& mesh, size_t triangle) {
    const glm::vec3 a = mesh.vertices[mesh.indices[3 * triangle]].position;
    const glm::vec3 b = mesh.vertices[mesh.indices[3 * triangle + 1]].position;
    const glm::vec3 c = mesh.vertices[mesh.indices[3 * triangle + 2]].position;
    return glm::cross(b - a, c - a);  // counter-clockwise winding -> points to the front
}

glm::vec3 centroid(const TriangleMesh& mesh, size_t triangle) {
    glm::vec3 sum(0.0f);
    for (int k = 0; k < 3; ++k) sum += mesh.vertices[mesh.indices[3 * triangle + k]].position;
    return sum / 3.0f;
}

// Volume enclosed by a closed mesh: positive only when every face winds counter-clockwise outside.
double signed_volume(const TriangleMesh& mesh) {
    double volume = 0.0;
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::dvec3 a = mesh.vertices[mesh.indices[3 * t]].position;
        const glm::dvec3 b = mesh.vertices[mesh.indices[3 * t + 1]].position;
        const glm::dvec3 c = mesh.vertices[mesh.indices[3 * t + 2]].position;
        volume += glm::dot(a, glm::cross(b, c)) / 6.0;
    }
    return volume;
}

void check_well_formed(const TriangleMesh& mesh) {
    REQUIRE(mesh.indices.size() % 3 == 0);
    for (uint32_t index : mesh.indices) REQUIRE(index < mesh.vertices.size());
    for (const Vertex& vertex : mesh.vertices) CHECK(glm::length(vertex.normal) == doctest::Approx(1.0).epsilon(1e-4));
}

// For convex shapes centred at the origin: every face and every vertex normal points away from it.
void check_convex_outward(const TriangleMesh& mesh) {
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {
        const glm::vec3 normal = face_normal(mesh, t);
        REQUIRE(glm::length(normal) > 0.0f);  // no degenerate triangles
        CHECK(glm::dot(normal, centroid(mesh, t)) > 0.0f);
        // The shading normals agree with the winding.
        for (int k = 0; k < 3; ++k) CHECK(glm::dot(normal, mesh.vertices[mesh.indices[3 * t + k]].normal) > 0.0f);
    }
}

Bounds bounds_of(const TriangleMesh& mesh) {
    Bounds bounds;
    for (const Vertex& vertex : mesh.vertices) bounds.extend(vertex.position);
    return bounds;
}

bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) { return glm::length(a - b) <= tolerance; }

Object shape(ShapeType type) {
    Object object;
    object.shape = type;
    object.name = "test";
    object.where = {"scene.toml", 12};
    return object;
}

std::optional<ConfigError> mesh_error(const Object& object) {
    try {
        build_object_mesh(object);
    } catch (const ConfigError& error) {
        return error;
    }
    return std::nullopt;
}

}  // namespace

TEST_CASE("plane: two upward triangles of the given size") {
    Object object = shape(ShapeType::plane);
    object.plane_size = {4.0f, 2.0f};
    const TriangleMesh mesh = build_object_mesh(object);
    check_well_formed(mesh);
    REQUIRE(mesh.triangle_count() == 2);
    for (size_t t = 0; t < 2; ++t) CHECK(glm::normalize(face_normal(mesh, t)).y == doctest::Approx(1.0));
    for (const Vertex& vertex : mesh.vertices) CHECK(vertex.normal == glm::vec3(0, 1, 0));
    const Bounds bounds = bounds_of(mesh);
    CHECK(near(bounds.min, {-2, 0, -1}));
    CHECK(near(bounds.max, {2, 0, 1}));
}

TEST_CASE("box: 12 triangles, 24 vertices, flat outward faces") {
    Object object = shape(ShapeType::box);
    object.box_size = {1.0f, 2.0f, 3.0f};
    const TriangleMesh mesh = build_object_mesh(object);
    check_well_formed(mesh);
    CHECK(mesh.triangle_count() == 12);
    CHECK(mesh.vertices.size() == 24);
    check_convex_outward(mesh);
    CHECK(signed_volume(mesh) == doctest::Approx(6.0));
    for (size_t t = 0; t < mesh.triangle_count(); ++t) {  // flat: vertex normals equal the face normal
        const glm::vec3 normal = glm::normalize(face_normal(mesh, t));
        for (int k = 0; k < 3; ++k) CHECK(near(mesh.vertices[mesh.indices[3 * t + k]].normal, normal));
    }
    const Bounds bounds = bounds_of(mesh);
    CHECK(near(bounds.min, {-0.5f, -1.0f, -1.5f}));
    CHECK(near(bounds.max, {0.5f, 1.0f, 1.5f}));
}

TEST_CASE("sphere: segments around, segments/2 rings, smooth radial normals") {
    Object object = shape(ShapeType::sphere);
    object.radius = 2.0f;
    object.segments = 16;
    const TriangleMesh mesh = build_object_mesh(object);
    check_well_formed(mesh);
    CHECK(mesh.triangle_count() == 16 * (2 * 8 - 2));  // the pole rings are fans
    check_convex_outward(mesh);
    for (const Vertex& vertex : mesh.vertices) {
        CHECK(glm::length(vertex.position) == doctest::Approx(2.0));
        CHECK(near(vertex.normal, vertex.position / 2.0f));
    }
    const double exact = 4.0 / 3.0 * kPi * 8.0;
    CHECK(signed_volume(mesh) > 0.85 * exact);
    CHECK(signed_volume(mesh) < exact);  // inscribed polyhedron
    const Bounds bounds = bounds_of(mesh);
    CHECK(bounds.max.y == doctest::Approx(2.0));
    CHECK(bounds.min.y == doctest::Approx(-2.0));

    object.segments = 64;
    const TriangleMesh fine = build_object_mesh(object);
    CHECK(fine.triangle_count() == 64 * (2 * 32 - 2));
    CHECK(signed_volume(fine) == doctest::Approx(exact).epsilon(0.01));
}

TEST_CASE("cylinder: smooth side, flat caps, centred on +y") {
    Object object = shape(ShapeType::cylinder);
    object.radius = 0.5f;
    object.height = 3.0f;
    object.segments = 12;
    const TriangleMesh mesh = build_object_mesh(object);
    check_well_formed(mesh);
    CHECK(mesh.triangle_count() == 4 * 12);  // side quads + two cap fans
    check_convex_outward(mesh);
    int up = 0, down = 0, side = 0;
    for (const Vertex& vertex : mesh.vertices) {
        if (vertex.normal == glm::vec3(0, 1, 0)) ++up;
        else if (vertex.normal == glm::vec3(0, -1, 0)) ++down;
        else if (std::abs(vertex.normal.y) < 1e-6f) ++side;
    }
    CHECK(up == 13);  // centre + ring
    CHECK(down == 13);
    CHECK(side == 2 * 13);
    const Bounds bounds = bounds_of(mesh);
    CHECK(near(bounds.min, {-0.5f, -1.5f, -0.5f}, 1e-4f));
    CHECK(near(bounds.max, {0.5f, 1.5f, 0.5f}, 1e-4f));
    const double exact = kPi * 0.25 * 3.0;
    CHECK(signed_volume(mesh) > 0.9 * exact);
    CHECK(signed_volume(mesh) < exact);
}

TEST_CASE("an OBJ mesh loads with its winding and normals") {
    Object object = shape(ShapeType::mesh);
    object.mesh_file = kData / "meshes/tetrahedron.obj";
    const TriangleMesh mesh = build_object_mesh(object);
    check_well_formed(mesh);
    CHECK(mesh.triangle_count() == 4);
    CHECK(signed_volume(mesh) == doctest::Approx(1.0 / 6.0));
}

TEST_CASE("real glTF models load with triangles and unit normals") {
    for (const char* model : {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
                              "glTF/CesiumMilkTruck/CesiumMilkTruck.gltf"}) {
        CAPTURE(model);
        Object object = shape(ShapeType::mesh);
        object.mesh_file = kAssimpModels / model;
        REQUIRE(std::filesystem::exists(object.mesh_file));
        const TriangleMesh mesh = build_object_mesh(object);
        CHECK(mesh.triangle_count() > 100);
        REQUIRE(mesh.indices.size() % 3 == 0);
        bool indices_valid = true, normals_unit = true;
        for (uint32_t index : mesh.indices) indices_valid &= index < mesh.vertices.size();
        for (const Vertex& vertex : mesh.vertices) normals_unit &= std::abs(glm::length(vertex.normal) - 1.0f) < 1e-3f;
        CHECK(indices_valid);
        CHECK(normals_unit);
        CHECK(bounds_of(mesh).radius() > 0.0f);
    }
}

TEST_CASE("mesh files that cannot be used are ConfigErrors at the object's line") {
    SUBCASE("missing") {
        Object object = shape(ShapeType::mesh);
        object.mesh_file = kData / "meshes/absent.glb";
        const auto error = mesh_error(object);
        REQUIRE(error);
        CHECK(error->file() == "scene.toml");
        CHECK(error->line() == 12);
        CHECK(std::string(error->what()).find("absent.glb") != std::string::npos);
    }
    SUBCASE("unreadable") {
        const std::filesystem::path garbage = std::filesystem::temp_directory_path() / "canopy_test_garbage.glb";
        std::ofstream(garbage, std::ios::binary) << "this is not a glTF file";
        Object object = shape(ShapeType::mesh);
        object.mesh_file = garbage;
        const auto error = mesh_error(object);
        std::filesystem::remove(garbage);
        REQUIRE(error);
        CHECK(error->line() == 12);
        CHECK(std::string(error->what()).find("cannot read mesh file") != std::string::npos);
    }
    SUBCASE("no triangles") {
        Object object = shape(ShapeType::mesh);
        object.mesh_file = kData / "meshes/points_only.obj";
        const auto error = mesh_error(object);
        REQUIRE(error);
        CHECK(error->line() == 12);
    }
}

TEST_CASE("Transform::matrix scales, rotates X then Y then Z, then translates") {
    Transform transform;
    transform.translate = {1, 2, 3};
    transform.rotate_degrees = {90, 0, 0};
    transform.scale = {2, 1, 1};
    CHECK(near(glm::vec3(transform.matrix() * glm::vec4(1, 0, 0, 1)), {3, 2, 3}));
    CHECK(near(glm::vec3(transform.matrix() * glm::vec4(0, 1, 0, 1)), {1, 2, 4}));  // +y -> +z about X

    Transform order;
    order.rotate_degrees = {0, 90, 90};
    // Y first: (1,0,0) -> (0,0,-1), which Z leaves alone. (Z first would give (0,1,0).)
    CHECK(near(glm::vec3(order.matrix() * glm::vec4(1, 0, 0, 1)), {0, 0, -1}));

    Transform placed = transform;
    placed.outer = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0));  // world = instance * object
    CHECK(near(glm::vec3(placed.matrix() * glm::vec4(1, 0, 0, 1)), {13, 2, 3}));
}

TEST_CASE("Bounds") {
    Bounds bounds;
    CHECK(bounds.empty());
    CHECK(bounds.radius() == 0.0f);
    bounds.extend({1, 2, 3});
    CHECK_FALSE(bounds.empty());
    CHECK(bounds.radius() == 0.0f);
    bounds.extend({-1, -2, 3});
    CHECK(bounds.center() == glm::vec3(0, 0, 3));
    CHECK(bounds.radius() == doctest::Approx(std::sqrt(5.0)));
}

TEST_CASE("scene_bounds covers every instance of every object in world space") {
    const Scene scene = parse_scene(R"(
[[light]]
type = "directional"

[[object]]
shape = "box"
size = 2
translate = [0, 1, 0]
instances = [ { translate = [5, 0, 0] }, { translate = [-5, 0, 0], scale = 2 } ]

[[object]]
shape = "sphere"
radius = 0.5
rotate = [90, 0, 0]
translate = [0, 0, 7]
)",
                                    "scene.toml");
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    REQUIRE(meshes.size() == 2);
    CHECK(meshes[0].triangle_count() == 12);
    const Bounds bounds = scene_bounds(scene, meshes);
    // The second instance scales the translated box: its centre moves to (-5, 2, 0), half-size 2;
    // the sphere reaches y = -0.5 and z = 7.5.
    CHECK(bounds.min.x == doctest::Approx(-7.0));
    CHECK(bounds.max.x == doctest::Approx(6.0));
    CHECK(bounds.min.y == doctest::Approx(-0.5));  // the sphere
    CHECK(bounds.max.y == doctest::Approx(4.0));
    CHECK(bounds.max.z == doctest::Approx(7.5).epsilon(1e-4));
    CHECK(bounds.min.z == doctest::Approx(-2.0));
}

TEST_CASE("instances may also be written as [[object.instances]] sub-tables") {
    const Scene scene = parse_scene(R"(
[[light]]
type = "directional"

[[object]]
shape = "box"
rotate = [0, 90, 0]
[[object.instances]]
translate = [0, 0, 3]
[[object.instances]]
scale = 2
)",
                                    "scene.toml");
    REQUIRE(scene.objects.size() == 1);
    const Object& box = scene.objects[0];
    REQUIRE(box.instances.size() == 2);
    // world = instance * object: rotate (1,0,0) to (0,0,-1), then move by +3 in z.
    CHECK(near(glm::vec3(box.instances[0].matrix() * glm::vec4(1, 0, 0, 1)), {0, 0, 2}));
    CHECK(near(glm::vec3(box.instances[1].matrix() * glm::vec4(1, 0, 0, 1)), {0, 0, -2}));
}

TEST_CASE("Light::size and Scene::shadow_light") {
    Light rect;
    rect.type = LightType::rect;
    rect.rect_size = {3, 4};
    CHECK(rect.size() == doctest::Approx(5.0));
    Light sphere;
    sphere.type = LightType::sphere;
    sphere.sphere_radius = 0.5f;
    CHECK(sphere.size() == doctest::Approx(1.0));
    Light spot;
    spot.type = LightType::spot;
    CHECK(spot.size() == 0.0f);

    Scene scene;
    CHECK(scene.shadow_light() == nullptr);
    spot.casts_shadows = false;
    scene.lights = {spot, rect, sphere};
    REQUIRE(scene.shadow_light() != nullptr);
    CHECK(scene.shadow_light() == &scene.lights[1]);
}
