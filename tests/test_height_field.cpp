// The heightfield shape: its grid's surface as the mesh triangulates it (shaders/height_field.h,
// which grass on a height map reads), its bounds, the hills and image maps, and its config.
#include "config/experiment_config.hpp"
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "report/image_files.hpp"
#include "scene/height_field.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>

using namespace canopy;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The height of the mesh triangle above (x, z), by its barycentrics in the xz plane; NaN when no
// triangle covers the point.
float mesh_height(const TriangleMesh& mesh, glm::vec2 p) {
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                        c = mesh.vertices[mesh.indices[t + 2]].position;
        const glm::vec2 v0 = glm::vec2(b.x, b.z) - glm::vec2(a.x, a.z), v1 = glm::vec2(c.x, c.z) - glm::vec2(a.x, a.z);
        const glm::vec2 v2 = p - glm::vec2(a.x, a.z);
        const float d = v0.x * v1.y - v1.x * v0.y;
        const float u = (v2.x * v1.y - v1.x * v2.y) / d, v = (v0.x * v2.y - v2.x * v0.y) / d;
        if (u >= -1e-6f && v >= -1e-6f && u + v <= 1.0f + 1e-6f) return a.y + u * (b.y - a.y) + v * (c.y - a.y);
    }
    return std::nanf("");
}

HeightField ramp_field() {  // 3 x 2 vertices over 4 x 2, heights chosen so the diagonal matters
    HeightField f;
    f.vertices = {3, 2};
    f.size = {4.0f, 2.0f};
    f.heights = {0.0f, 1.0f, 0.5f,   // z = -1
                 2.0f, 0.0f, 3.0f};  // z = +1
    return f;
}

}  // namespace

TEST_CASE("a height field reads the surface its mesh draws, split along the quads' (1,0)-(0,1) diagonal") {
    const HeightField field = hills_height_field({6.0f, 4.0f}, {9, 7}, 2, 5, 1.5f);
    const TriangleMesh mesh = build_height_field_mesh(field);
    CHECK(mesh.vertices.size() == 63);
    CHECK(mesh.triangle_count() == 8 * 6 * 2);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> x(-3.0f, 3.0f), z(-2.0f, 2.0f);
    for (int i = 0; i < 500; ++i) {
        const glm::vec2 p(x(rng), z(rng));
        CHECK(field.at(p) == doctest::Approx(mesh_height(mesh, p)).epsilon(1e-5));
    }
    // On a quad's centre the split diagonal's midpoint: not the other diagonal's, not the bilinear mean.
    const HeightField ramp = ramp_field();
    CHECK(ramp.at({-1.0f, 0.0f}) == doctest::Approx(0.5f * (1.0f + 2.0f)));
    CHECK(ramp.at({1.0f, 0.0f}) == doctest::Approx(0.5f * (0.5f + 0.0f)));
    CHECK(ramp.at({-2.0f, -1.0f}) == 0.0f);
    CHECK(ramp.at({2.0f, 1.0f}) == 3.0f);
    CHECK(ramp.at({-9.0f, 9.0f}) == 2.0f);  // outside: the nearest edge
}

TEST_CASE("a height field's mesh faces up with unit normals") {
    const TriangleMesh mesh = build_height_field_mesh(hills_height_field({8.0f, 8.0f}, {17, 17}, 3, 1, 3.0f));
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.vertices[mesh.indices[t]].position, b = mesh.vertices[mesh.indices[t + 1]].position,
                        c = mesh.vertices[mesh.indices[t + 2]].position;
        REQUIRE(glm::cross(b - a, c - a).y > 0.0f);
    }
    for (const Vertex& v : mesh.vertices) {
        CHECK(glm::length(v.normal) == doctest::Approx(1.0f));
        CHECK(v.normal.y > 0.0f);
    }
}

TEST_CASE("a height field's range over a rectangle holds every height in it") {
    const HeightField field = hills_height_field({10.0f, 10.0f}, {33, 33}, 3, 9, 2.0f);
    std::mt19937 rng(1);
    std::uniform_real_distribution<float> coordinate(-5.0f, 5.0f);
    for (int i = 0; i < 50; ++i) {
        glm::vec2 lo(coordinate(rng), coordinate(rng)), hi(coordinate(rng), coordinate(rng));
        const glm::vec2 a = glm::min(lo, hi), b = glm::max(lo, hi);
        const glm::vec2 range = field.range(a, b);
        float low = 1e30f, high = -1e30f;
        for (int s = 0; s <= 40; ++s)
            for (int t = 0; t <= 40; ++t) {
                const float h = field.at(glm::mix(a, b, glm::vec2(s, t) / 40.0f));
                low = std::min(low, h);
                high = std::max(high, h);
            }
        CHECK(range.x <= low);
        CHECK(range.y >= high);
        CHECK(range.y - range.x <= 2.0f);
    }
}

TEST_CASE("hills are seeded, smooth and within [0, height_scale]") {
    const HeightField a = hills_height_field({16.0f, 16.0f}, {65, 65}, 3, 1, 2.5f);
    const HeightField b = hills_height_field({16.0f, 16.0f}, {65, 65}, 3, 1, 2.5f);
    const HeightField c = hills_height_field({16.0f, 16.0f}, {65, 65}, 3, 2, 2.5f);
    CHECK(a.heights == b.heights);
    CHECK(a.heights != c.heights);
    float low = 1e30f, high = -1e30f, steepest = 0.0f;
    for (uint32_t z = 0; z < 65; ++z)
        for (uint32_t x = 0; x < 65; ++x) {
            low = std::min(low, a.vertex(x, z));
            high = std::max(high, a.vertex(x, z));
            if (x > 0) steepest = std::max(steepest, std::abs(a.vertex(x, z) - a.vertex(x - 1, z)));
        }
    CHECK(low >= 0.0f);
    CHECK(high <= 2.5f);
    CHECK(high - low > 0.5f);         // hills, not a plane
    CHECK(steepest < 0.1f * 2.5f);    // and smooth from one vertex to the next (0.25 apart)
}

TEST_CASE("a height map image gives one vertex a pixel, its first row along -z and first column along -x") {
    Image image(3, 2);
    image.pixels.assign(image.pixels.size(), 0.0f);
    image.pixels[0] = 1.0f;                  // pixel (0, 0)
    image.pixels[(1 * 3 + 2) * 4] = 0.5f;    // pixel (2, 1)
    const HeightField field = height_field_from_image(image, {4.0f, 2.0f}, 2.0f, "map.png");
    CHECK(field.vertices == glm::uvec2(3, 2));
    CHECK(field.at({-2.0f, -1.0f}) == 2.0f);
    CHECK(field.at({2.0f, 1.0f}) == 1.0f);
    CHECK(field.at({2.0f, -1.0f}) == 0.0f);
    image.pixels[4] = 1.5f;
    try {
        height_field_from_image(image, {4.0f, 2.0f}, 2.0f, "map.png");
        FAIL("a value above 1 must be refused");
    } catch (const std::invalid_argument& e) {
        CHECK(contains(e.what(), "map.png: pixel (1, 0) is 1.5, outside [0, 1]"));
    }
    CHECK_THROWS_AS(height_field_from_image(Image(1, 5), {1.0f, 1.0f}, 1.0f, "thin.png"), std::invalid_argument);
}

TEST_CASE("a heightfield object loads from its config, and its mistakes are named at their lines") {
    test::TempFolder folder;
    const std::string head = "[scene]\nname = \"h\"\n[[light]]\ntype = \"directional\"\n[[object]]\nshape = \"heightfield\"\n"
                             "size = [8, 4]\n";
    const Scene hills = load_scene(folder.write("hills.toml", head + "height_scale = 2\nvertices = [9, 5]\nperiods = 2\n"));
    REQUIRE(hills.objects.size() == 1);
    REQUIRE(hills.objects[0].height_field);
    CHECK(hills.objects[0].height_field->vertices == glm::uvec2(9, 5));
    CHECK(hills.objects[0].height_field->heights == hills_height_field({8.0f, 4.0f}, {9, 5}, 2, 1, 2.0f).heights);
    CHECK(build_object_mesh(hills.objects[0]).triangle_count() == 8 * 4 * 2);

    Image map(2, 2);
    map.pixels.assign(map.pixels.size(), 0.25f);
    std::filesystem::create_directories(folder.path() / "maps");
    write_exr(folder.path() / "maps" / "h.exr", map);
    const Scene from_file =
        load_scene(folder.write("file.toml", head + "height_map = \"file\"\nheight_map_file = \"maps/h.exr\"\nheight_scale = 4\n"));
    CHECK(from_file.objects[0].height_field->at({0.0f, 0.0f}) == 1.0f);
    CHECK(from_file.objects[0].height_map_file == std::filesystem::absolute(folder.path() / "maps" / "h.exr").lexically_normal());

    const auto error_in = [&](const std::string& body) {
        return test::config_error_of([&] { load_scene(folder.write("bad.toml", head + body)); });
    };
    const auto kind = error_in("height_map = \"mountains\"\n");
    REQUIRE(kind);
    CHECK(kind->line() == 8);
    CHECK(contains(kind->what(), "must be \"hills\" or \"file\""));
    const auto missing = error_in("height_map = \"file\"\nheight_map_file = \"maps/none.png\"\n");
    REQUIRE(missing);
    CHECK(missing->line() == 9);
    CHECK(contains(missing->what(), "height map 'maps/none.png' not found"));
    const auto grid = error_in("vertices = 1\n");
    REQUIRE(grid);
    CHECK(contains(grid->what(), "whole numbers in [2, 2048]"));
    const auto not_for_files = error_in("height_map = \"file\"\nheight_map_file = \"maps/h.exr\"\nperiods = 3\n");
    REQUIRE(not_for_files);
    CHECK(not_for_files->line() == 10);
    CHECK(error_in("radius = 2\n"));                     // a sphere's key
    CHECK(test::config_error_of([&] { load_scene(folder.write("plane.toml",
        "[scene]\nname = \"p\"\n[[object]]\nshape = \"plane\"\nheight_scale = 2\n")); }));  // a heightfield's key on a plane
}

TEST_CASE("an experiment's config hash follows the height map image it reads") {
    test::TempFolder folder;
    Image map(2, 2);
    map.pixels.assign(map.pixels.size(), 0.25f);
    write_exr(folder.path() / "h.exr", map);
    folder.write("scene.toml", "[scene]\nname = \"h\"\n[[light]]\ntype = \"directional\"\n[[object]]\nshape = \"heightfield\"\n"
                               "size = [8, 4]\nheight_map = \"file\"\nheight_map_file = \"h.exr\"\n");
    const auto experiment_file = folder.write("experiment.toml", "[experiment]\nname = \"e\"\nscenes = [\"scene.toml\"]\n"
                                                                 "[[technique]]\nname = \"shadow.hard\"\n");
    const std::string before = load_experiment(experiment_file, TechniqueRegistry::instance()).config_hash;
    map.pixels[0] = 0.5f;
    write_exr(folder.path() / "h.exr", map);
    CHECK(load_experiment(experiment_file, TechniqueRegistry::instance()).config_hash != before);
}
