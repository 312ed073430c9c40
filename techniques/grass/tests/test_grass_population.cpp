// The grass field as a scene population (common/grass_population.hpp): read from a scene's
// [[population]] with kind = "grass", its copies are the field's cells (placed and mirrored as
// field_point places them), and the reference's alpha test thins and cuts exactly the blades
// for_each_drawn_blade enumerates and blade_alpha.h outlines. Each breakage of the placement,
// the mirror's corner permutation or the thinning fails a check here.
#include "../common/grass_field.hpp"
#include "../common/grass_population.hpp"
#include "../shaders/blade_alpha.h"
#include "../shaders/grass_terrain.h"

#include "config/scene_config.hpp"
#include "reference/embree_scene.hpp"
#include "scene/geometry.hpp"
#include "scene/height_field.hpp"
#include "report/image_files.hpp"
#include "support/config_error_of.hpp"
#include "support/temp_folder.hpp"
#include "support/reference_hits.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <cmath>
#include <map>
#include <memory>
#include <set>
#include <string>

using namespace canopy;
using namespace canopy::grass;

namespace {

const char* kScene = R"([scene]
name = "lawn"
[[light]]
type = "directional"
direction = [0, -1, 0]
[[object]]
name = "ground"
shape = "plane"
size = [8, 8]
[[population]]
name = "lawn"
kind = "grass"
albedo = [0.2, 0.6, 0.1]
params = { cells_x = 3, cells_z = 2, blades = 50, cell_size = 1.5, centre_x = 0.5 }
)";

std::string with_params(const std::string& params) {
    std::string text = kScene;
    const size_t at = text.find("params = {");
    return text.substr(0, at) + "params = { " + params + " }\n";
}

GrassPopulationSpec small_spec() {
    GrassPopulationSpec spec;
    spec.patch.blades = 80;
    spec.patch.subdivisions = 2;
    spec.field.cells = {5, 4};
    spec.field.cell_size = 0.8f;
    spec.field.origin = {-2.0f, 0.1f, -1.6f};
    spec.field.mirror_seed = 3;
    // A ramp across x and a step across z, so every mirror permutes the corners differently.
    spec.field.density.width = 6;
    spec.field.density.height = 2;
    for (uint32_t z = 0; z < 2; ++z)
        for (uint32_t x = 0; x < 6; ++x) spec.field.density.values.push_back(0.1f + 0.15f * float(x) + 0.05f * float(z));
    return spec;
}

// A point well inside blade b's outline on its first segment's first triangle: barycentrics
// for the strip point u = 1/2, just above the root.
struct Inside {
    uint32_t triangle;
    float u, v;
};
Inside inside_blade(uint32_t blade, uint32_t triangles_per_blade) {
    // Triangle 0 of a segment is (left0, right0, left1): u = 1/2 at a small v is 0.5 (right0) + a
    // small share of left1.
    return {blade * triangles_per_blade, 0.45f, 0.05f};
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("grass population: a scene's kind = \"grass\" generates one copy per cell from typed parameters") {
    const Scene scene = parse_scene(kScene, "lawn.toml");
    REQUIRE(scene.populations.size() == 1);
    const Population& population = scene.populations[0];
    CHECK(population.kind == "grass");
    REQUIRE(population.family);
    CHECK(population.family->instances.size() == 6);
    CHECK(population.params.integer("blades") == 50);
    CHECK(population.prototype.material.albedo == glm::vec3(0.2f, 0.6f, 0.1f));
    // 50 blades of 10 triangles (4 subdivisions) and their per-vertex data.
    CHECK(population.family->prototype.triangle_count() == 500);
    CHECK(population.family->vertex_data.size() == population.family->prototype.vertices.size());
    // The field is centred on (0.5, 0): 3 x 1.5 wide in x, 2 x 1.5 in z.
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    const Bounds bounds = scene_bounds(scene, meshes);
    CHECK(bounds.min.x == doctest::Approx(-4.0f));  // the ground plane
    // Roots lie in the field's rectangle, [-1.75, 2.75] x [-1.5, 1.5]; blades lean out of it by less than
    // their height (at most 0.35 patch units of 1.5).
    Bounds roots, blades;
    for (const PopulationInstance& copy : population.family->instances)
        for (size_t i = 0; i < population.family->prototype.vertices.size(); ++i) {
            const glm::vec3 p(copy.model * glm::vec4(population.family->prototype.vertices[i].position, 1.0f));
            blades.extend(p);
            const glm::vec4 root = population.family->vertex_data[i].data[1];
            roots.extend(glm::vec3(copy.model * glm::vec4(root.x, 0.0f, root.y, 1.0f)));
        }
    CHECK(roots.min.x >= -1.75f);
    CHECK(roots.max.x <= 2.75f);
    CHECK(roots.min.z >= -1.5f);
    CHECK(roots.max.z <= 1.5f);
    CHECK(roots.max.x - roots.min.x > 4.4f);  // and fill it
    CHECK(roots.max.z - roots.min.z > 2.9f);
    CHECK(blades.min.x > -1.75f - 0.525f);
    CHECK(blades.max.y <= 0.35f * 1.5f + 1e-5f);
    CHECK(blades.min.y == doctest::Approx(0.0f));
}

TEST_CASE("grass population: bad parameters name the line and the fix") {
    SUBCASE("an unknown parameter") {
        const std::string text = with_params("cells_x = 2, bladez = 4");
        const auto error = test::config_error_of([&] { parse_scene(text, "lawn.toml"); });
        REQUIRE(error);
        CHECK(error->line() == 1 + std::count(text.begin(), text.begin() + long(text.find("bladez")), '\n'));
        CHECK(std::string(error->what()).find("bladez") != std::string::npos);
    }
    SUBCASE("out of range") {
        const auto error = test::config_error_of([] { parse_scene(with_params("density = 1.5"), "lawn.toml"); });
        REQUIRE(error);
        CHECK(std::string(error->what()).find("density") != std::string::npos);
    }
    SUBCASE("each in range, together impossible") {
        const auto error =
            test::config_error_of([] { parse_scene(with_params("height_min = 0.5, height_max = 0.2"), "lawn.toml"); });
        REQUIRE(error);
        CHECK(std::string(error->what()).find("height") != std::string::npos);
        CHECK(std::string(error->what()).find("cannot be generated") != std::string::npos);
    }
    SUBCASE("a density map whose low end is above its high end") {
        const auto error = test::config_error_of(
            [] { parse_scene(with_params("density_map = \"ramp_x\", density = 0.3, density_low = 0.6"), "lawn.toml"); });
        REQUIRE(error);
        CHECK(std::string(error->what()).find("density_low = 0.6 is above density = 0.3") != std::string::npos);
        // A uniform field reads no low end.
        CHECK_NOTHROW(parse_scene(with_params("density = 0.3, density_low = 0.6"), "lawn.toml"));
    }
    SUBCASE("a field the reference cannot hold is refused before it is generated") {
        const auto error = test::config_error_of(
            [] { parse_scene(with_params("cells_x = 4096, cells_z = 4096, blades = 1048576, subdivisions = 64"), "lawn.toml"); });
        REQUIRE(error);
        CHECK(std::string(error->what()).find("copies a population may have") != std::string::npos);
        const auto triangles = test::config_error_of(
            [] { parse_scene(with_params("blades = 1048576, subdivisions = 64"), "lawn.toml"); });
        REQUIRE(triangles);
        CHECK(std::string(triangles->what()).find("a prototype may have") != std::string::npos);
    }
    SUBCASE("two populations of one name") {
        const std::string text = std::string(kScene) + "[[population]]\nname = \"lawn\"\nkind = \"grass\"\n";
        const auto error = test::config_error_of([&] { parse_scene(text, "lawn.toml"); });
        REQUIRE(error);
        CHECK(std::string(error->what()).find("a second population is named 'lawn'") != std::string::npos);
        CHECK(error->line() == 1 + std::count(text.begin(), text.begin() + long(text.rfind("name = \"lawn\"")), '\n'));
    }
    SUBCASE("an unknown kind lists the kinds") {
        std::string text = kScene;
        text.replace(text.find("kind = \"grass\""), 14, "kind = \"gras\"");
        const auto error = test::config_error_of([&] { parse_scene(text, "lawn.toml"); });
        REQUIRE(error);
        CHECK(error->hint().find("did you mean 'grass'") != std::string::npos);
        CHECK(error->hint().find("scatter") != std::string::npos);
    }
}

TEST_CASE("grass population: density_map = \"file\" reads an image as the field's map, its first row along -z, its first column along -x") {
    test::TempFolder folder;
    std::filesystem::create_directories(folder.path() / "maps");
    Image map(2, 2);  // row 0: 0.0 0.4; row 1: 0.6 1.0 (x, then z)
    const float values[2][2] = {{0.0f, 0.4f}, {0.6f, 1.0f}};
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) map.at(x, y)[0] = values[y][x];
    write_exr(folder.path() / "maps" / "density.exr", map);
    const auto scene_with = [&](const std::string& params) {
        return folder.write("scenes/lawn.toml", std::string(kScene).substr(0, std::string(kScene).find("params = {")) +
                                                    "params = { " + params + " }\n");
    };
    const std::string field = "cells_x = 2, cells_z = 2, cell_size = 1, centre_x = 0, blades = 20, mirror = false, ";
    const Scene scene = load_scene(scene_with(field + "density_map = \"file\", density_map_file = \"../maps/density.exr\""));
    const auto copies = generate_instances(scene.populations.at(0));
    REQUIRE(copies->size() == 4);
    int checked = 0;
    for (const PopulationInstance& copy : *copies) {
        // The corners the field's outer corners are (corner order x0z0, x1z0, x0z1, x1z1): the map's
        // clamped corner texels.
        const glm::vec3 origin(copy.model[3]);
        CAPTURE(origin.x);
        CAPTURE(origin.z);
        if (origin.x < -0.5f && origin.z < -0.5f) { CHECK(copy.data.x == doctest::Approx(0.0f)); ++checked; }
        if (origin.x > -0.5f && origin.z < -0.5f) { CHECK(copy.data.y == doctest::Approx(0.4f)); ++checked; }
        if (origin.x < -0.5f && origin.z > -0.5f) { CHECK(copy.data.z == doctest::Approx(0.6f)); ++checked; }
        if (origin.x > -0.5f && origin.z > -0.5f) { CHECK(copy.data.w == doctest::Approx(1.0f)); ++checked; }
    }
    CHECK(checked == 4);
    // density_low and density map the image's 0 and 1.
    const Scene scaled = load_scene(
        scene_with(field + "density_map = \"file\", density_map_file = \"../maps/density.exr\", density_low = 0.2, density = 0.7"));
    for (const PopulationInstance& copy : *generate_instances(scaled.populations.at(0)))
        if (copy.model[3].x > -0.5f && copy.model[3].z > -0.5f) CHECK(copy.data.w == doctest::Approx(0.7f));
    // The same as a direct call, value by value.
    const grass::DensityMap direct = density_map_from_image(map, 0.0f, 1.0f, "map");
    CHECK(direct.width == 2);
    CHECK(direct.height == 2);
    CHECK(direct.values == std::vector<float>{0.0f, 0.4f, 0.6f, 1.0f});

    SUBCASE("mistakes name the line and the fix") {
        const auto missing = test::config_error_of(
            [&] { load_scene(scene_with(field + "density_map = \"file\", density_map_file = \"../maps/none.png\"")); });
        REQUIRE(missing);
        CHECK(std::string(missing->what()).find("not a file") != std::string::npos);
        CHECK(missing->line() == 14);
        const auto unnamed = test::config_error_of([&] { load_scene(scene_with(field + "density_map = \"file\"")); });
        REQUIRE(unnamed);
        CHECK(std::string(unnamed->what()).find("needs density_map_file") != std::string::npos);
        const auto unread = test::config_error_of(
            [&] { load_scene(scene_with(field + "density_map_file = \"../maps/density.exr\"")); });
        REQUIRE(unread);
        CHECK(std::string(unread->what()).find("set density_map = \"file\"") != std::string::npos);
        Image bright(1, 1);
        bright.at(0, 0)[0] = 1.5f;
        write_exr(folder.path() / "maps" / "bright.exr", bright);
        const auto out_of_range = test::config_error_of(
            [&] { load_scene(scene_with(field + "density_map = \"file\", density_map_file = \"../maps/bright.exr\"")); });
        REQUIRE(out_of_range);
        CHECK(std::string(out_of_range->what()).find("outside [0, 1]") != std::string::npos);
        const auto not_a_path = test::config_error_of(
            [&] { load_scene(scene_with(field + "density_map = \"file\", density_map_file = 3")); });
        REQUIRE(not_a_path);
        CHECK(std::string(not_a_path->what()).find("file path") != std::string::npos);
    }
}

TEST_CASE("grass population: the copies place every blade where field_point does, mirrored per cell") {
    const GrassPopulationSpec spec = small_spec();
    const FamilyPopulation population = generate_grass_population(spec);
    const BladePatch patch = generate_blade_patch(spec.patch);
    REQUIRE(population.instances.size() == 20);
    std::set<std::pair<float, float>> signs_seen;
    for (uint32_t z = 0; z < spec.field.cells.y; ++z)
        for (uint32_t x = 0; x < spec.field.cells.x; ++x) {
            const glm::ivec2 cell{int(x), int(z)};
            const PopulationInstance& copy = population.instances[z * spec.field.cells.x + x];
            const glm::vec2 s = mirror_signs(spec.field, cell);
            signs_seen.insert({s.x, s.y});
            for (size_t i = 0; i < patch.vertices.size(); i += 7) {
                const glm::vec3 expected = field_point(spec.field, cell, patch.vertices[i].position);
                const glm::vec3 placed(copy.model * glm::vec4(patch.vertices[i].position, 1.0f));
                CHECK(glm::length(placed - expected) < 1e-5f);
            }
            // The normal matrix is the model's inverse transpose.
            const glm::mat3 normal(copy.normal_matrix[0], copy.normal_matrix[1], copy.normal_matrix[2]);
            const glm::mat3 expected = glm::transpose(glm::inverse(glm::mat3(copy.model)));
            for (int c = 0; c < 3; ++c) CHECK(glm::length(normal[c] - expected[c]) < 1e-5f);
        }
    CHECK(signs_seen.size() == 4);  // every mirror occurs, so each permutation below is exercised

    GrassPopulationSpec plain = spec;
    plain.field.mirror = false;
    const FamilyPopulation unmirrored = generate_grass_population(plain);
    for (const PopulationInstance& copy : unmirrored.instances) {
        CHECK(copy.model[0][0] > 0.0f);
        CHECK(copy.model[2][2] > 0.0f);
    }
}

TEST_CASE("grass population on a terrain: each blade's root is lifted onto the ground under it, in the field, the "
          "copies and the reference's offsets alike") {
    GrassPopulationSpec spec = small_spec();  // 5 x 4 cells of 0.8, corner (-2, -1.6): centred on (0, 0)
    auto hills = std::make_shared<HeightField>(hills_height_field({4.0f, 3.2f}, {6, 5}, 2, 7, 1.2f));
    spec.field.ground = {hills, glm::vec3(0.0f, 0.3f, 0.0f), "ground"};
    const FamilyPopulation population = generate_grass_population(spec);
    const BladePatch patch = generate_blade_patch(spec.patch);
    REQUIRE(population.vertex_offset);
    const auto ground_at = [&](glm::vec2 xz) { return 0.3f + hills->at(xz); };
    // The field: every drawn root stands origin.y above the terrain.
    uint64_t roots = 0;
    for_each_drawn_blade(spec.field, patch, [&](const FieldBlade& b) {
        ++roots;
        CHECK(b.root.y == doctest::Approx(0.1f + ground_at({b.root.x, b.root.z})).epsilon(1e-5));
    });
    CHECK(roots > 100);
    // The copies: model (lifted to the cell's first corner) plus the packed lift, at every vertex
    // of every blade, put the root where the terrain is, whatever the cell's mirror.
    for (uint32_t c = 0; c < population.instances.size(); ++c) {
        const PopulationInstance& copy = population.instances[c];
        for (uint32_t v = 0; v < patch.vertices.size(); v += 5) {
            const BladeVertex& vertex = patch.vertices[v];
            const glm::vec3 offset = population.vertex_offset(c, v);
            CHECK(offset.x == 0.0f);
            CHECK(offset.z == 0.0f);
            const glm::vec3 root(copy.model * glm::vec4(vertex.root + offset, 1.0f));
            CHECK(root.y == doctest::Approx(0.1f + ground_at({root.x, root.z})).epsilon(1e-5));
            // The whole blade moves with its root.
            const glm::vec3 moved(copy.model * glm::vec4(vertex.position + offset, 1.0f));
            const glm::vec3 flat(copy.model * glm::vec4(vertex.position, 1.0f));
            CHECK(moved.y - flat.y == doctest::Approx(root.y - glm::vec3(copy.model * glm::vec4(vertex.root, 1.0f)).y).epsilon(1e-5));
        }
    }
    // On flat ground: no offsets, nothing packed.
    const FamilyPopulation flat = generate_grass_population(small_spec());
    CHECK_FALSE(flat.vertex_offset);
    for (const PopulationInstance& copy : flat.instances)
        for (int corner = 0; corner < 3; ++corner) CHECK(copy.normal_matrix[corner].w == 0.0f);
}

TEST_CASE("grass population on a terrain: the heightfield must be the field's cells, and a terrain key must name one") {
    const auto scene_with = [](const std::string& ground, const std::string& population_keys, const std::string& params) {
        return "[scene]\nname = \"t\"\n[[light]]\ntype = \"directional\"\n[[object]]\nname = \"ground\"\n" + ground +
               "[[object]]\nname = \"ball\"\nshape = \"sphere\"\n[[population]]\nname = \"lawn\"\nkind = \"grass\"\n" +
               population_keys + "params = { blades = 20, " + params + " }\n";
    };
    const std::string fits = "shape = \"heightfield\"\nsize = [3, 2]\nvertices = [4, 3]\n";
    CHECK(parse_scene(scene_with(fits, "terrain = \"ground\"\n", "cells_x = 3, cells_z = 2"), "t.toml").populations[0].ground.terrain);

    const auto misfit = test::config_error_of([&] {
        parse_scene(scene_with(fits, "terrain = \"ground\"\n", "cells_x = 4, cells_z = 2"), "t.toml");
    });
    REQUIRE(misfit);
    CHECK(contains(misfit->what(), "give it vertices = [5, 3] (it has [4, 3]), size = [4, 2] (it has [3, 2])"));
    const auto off_centre = test::config_error_of([&] {
        parse_scene(scene_with(fits + "translate = [0.5, 0, 0]\n", "terrain = \"ground\"\n", "cells_x = 3, cells_z = 2"),
                    "t.toml");
    });
    REQUIRE(off_centre);
    CHECK(contains(off_centre->what(), "translate x, z = 0, 0 (it has 0.5, 0)"));
    const auto rotated = test::config_error_of([&] {
        parse_scene(scene_with(fits + "rotate = [0, 90, 0]\n", "terrain = \"ground\"\n", "cells_x = 3, cells_z = 2"), "t.toml");
    });
    REQUIRE(rotated);
    CHECK(contains(rotated->what(), "moved by `translate` alone"));
    const auto no_object = test::config_error_of([&] {
        parse_scene(scene_with(fits, "terrain = \"hill\"\n", "cells_x = 3, cells_z = 2"), "t.toml");
    });
    REQUIRE(no_object);
    CHECK(no_object->line() == 16);
    CHECK(contains(no_object->what(), "terrain = \"hill\" names no object"));
    CHECK(contains(no_object->hint(), "heightfield objects: ground"));
    const auto sphere = test::config_error_of([&] {
        parse_scene(scene_with(fits, "terrain = \"ball\"\n", "cells_x = 3, cells_z = 2"), "t.toml");
    });
    REQUIRE(sphere);
    CHECK(contains(sphere->what(), "names a sphere, not a heightfield"));
}

TEST_CASE("grass population: the reference thins exactly the blades the field draws and cuts their outline") {
    const GrassPopulationSpec spec = small_spec();
    const FamilyPopulation population = generate_grass_population(spec);
    const BladePatch patch = generate_blade_patch(spec.patch);
    const uint32_t per_blade = triangles_per_blade(spec.patch.subdivisions);
    REQUIRE(population.opaque);
    std::set<std::pair<uint32_t, uint32_t>> drawn;  // (copy, blade)
    const uint64_t count = for_each_drawn_blade(spec.field, patch, [&](const FieldBlade& b) {
        drawn.insert({uint32_t(b.cell.y) * spec.field.cells.x + uint32_t(b.cell.x), b.blade});
    });
    const uint64_t all = uint64_t(population.instances.size()) * patch.blades.size();
    CAPTURE(count);
    CHECK(count > all / 5);  // the map thins some and keeps some
    CHECK(count < all * 4 / 5);
    uint64_t agree = 0;
    for (uint32_t copy = 0; copy < population.instances.size(); ++copy)
        for (uint32_t blade = 0; blade < patch.blades.size(); ++blade) {
            const Inside p = inside_blade(blade, per_blade);
            const bool opaque = population.opaque(copy, p.triangle, p.u, p.v);
            agree += opaque == (drawn.count({copy, blade}) == 1);
        }
    CHECK(agree == all);

    // The outline: a drawn blade is cut outside |u - 1/2| <= (1 - v^k)/2. Triangle 0 of a blade
    // spans (left0, right0, left1): barycentrics (0.5, 0.5) lie on its left1-right0 edge, and at
    // the root the strip is full width, so (u weight 1, v 0) = right0 (u = 1) is on the outline;
    // near the tip the strip narrows to a point.
    const uint32_t copy = drawn.begin()->first, blade = drawn.begin()->second;
    const uint32_t tip_triangle = blade * per_blade + per_blade - 2;  // the last segment's first triangle
    CHECK(population.opaque(copy, blade * per_blade, 0.45f, 0.05f));
    CHECK_FALSE(population.opaque(copy, tip_triangle, 0.02f, 0.9f));   // u ~ 0 near the tip: outside
    // The albedo scale is the blade's colour, in [1 - v_b, 1] * [1 - v_v, 1].
    REQUIRE(population.albedo_scale);
    const float scale = population.albedo_scale(copy, blade * per_blade, 0.3f, 0.3f);
    CHECK(scale <= 1.0f);
    CHECK(scale >= (1.0f - spec.patch.blade_colour_variation) * (1.0f - spec.patch.vertex_colour_variation) - 1e-6f);
}

TEST_CASE("grass population: density 0 draws nothing, density 1 everything, at any mirror") {
    for (float density : {0.0f, 1.0f}) {
        GrassPopulationSpec spec = small_spec();
        spec.field.density = DensityMap{1, 1, {density}};
        const FamilyPopulation population = generate_grass_population(spec);
        const uint32_t per_blade = triangles_per_blade(spec.patch.subdivisions);
        uint32_t opaque = 0;
        for (uint32_t copy = 0; copy < population.instances.size(); ++copy)
            for (uint32_t blade = 0; blade < spec.patch.blades; ++blade)
                opaque += population.opaque(copy, blade * per_blade, 0.45f, 0.05f);
        CHECK(opaque == (density == 0.0f ? 0u : uint32_t(population.instances.size()) * spec.patch.blades));
    }
}

TEST_CASE("grass population: Embree's instanced cells hit only the blades their own cell draws, where it draws them") {
    // The small field with its density ramp in the lawn scene: each cell an Embree instance of
    // the one patch, so a wrong copy in the filter (thinning by another cell's densities) or in
    // resolve() (another cell's label and normals) shows up here.
    Scene scene = parse_scene(kScene, "lawn.toml");
    const GrassPopulationSpec spec = small_spec();
    scene.populations[0].family = std::make_shared<const FamilyPopulation>(generate_grass_population(spec));
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    const BladePatch patch = generate_blade_patch(spec.patch);
    const uint32_t per_blade = triangles_per_blade(spec.patch.subdivisions);
    const uint32_t triangles = uint32_t(patch.blades.size()) * per_blade;
    CHECK(embree.stored_triangle_count() == 2 + triangles);
    CHECK(embree.triangle_count() == 2 + uint64_t(triangles) * 20);

    std::map<std::pair<uint32_t, uint32_t>, glm::vec3> drawn;  // (copy, blade) -> world root
    for_each_drawn_blade(spec.field, patch, [&](const FieldBlade& b) {
        drawn[{uint32_t(b.cell.y) * spec.field.cells.x + uint32_t(b.cell.x), b.blade}] = b.root;
    });
    int blade_hits = 0, ground_hits = 0, thinned = 0, far_from_root = 0, upright_normals = 0;
    for (int j = 0; j < 160; ++j)
        for (int i = 0; i < 200; ++i) {
            const RTCRayHit ray = test::trace_down(embree, -2.0f + 4.0f * (float(i) + 0.5f) / 200.0f,
                                                   -1.6f + 3.2f * (float(j) + 0.5f) / 160.0f, 5.0f, 10.0f);
            REQUIRE(ray.hit.geomID != RTC_INVALID_GEOMETRY_ID);  // the ground lies under every ray
            const EmbreeHit hit = embree.resolve(ray.hit);
            if (embree.geometry(hit.geometry).population < 0) {
                ++ground_hits;
                continue;
            }
            ++blade_hits;
            const uint32_t copy = uint32_t(hit.primitive / triangles);
            const uint32_t blade = uint32_t(hit.primitive % triangles) / per_blade;
            const auto found = drawn.find({copy, blade});
            if (found == drawn.end()) {
                ++thinned;
                continue;
            }
            // A blade reaches less than 0.4 patch units from its root (a tip 0.35 up, tilted 25
            // degrees, its rise halved at most by the pull).
            const glm::vec2 at(ray.ray.org_x, ray.ray.org_z);
            far_from_root += glm::length(at - glm::vec2(found->second.x, found->second.z)) > 0.4f * spec.field.cell_size;
            // The interpolated normal in world space: unit, and near the face's own normal.
            const glm::vec3 n = embree.shading_normal(hit.geometry, hit.primitive, ray.hit.u, ray.hit.v);
            upright_normals += std::abs(glm::length(n) - 1.0f) < 1e-4f && std::abs(glm::dot(glm::normalize(hit.geometric_normal), n)) > 0.2f;
        }
    CAPTURE(blade_hits);
    CAPTURE(ground_hits);
    CHECK(blade_hits > 300);
    CHECK(ground_hits > 1000);
    CHECK(thinned == 0);
    CHECK(far_from_root == 0);
    CHECK(upright_normals == blade_hits);
}

TEST_CASE("grass on a terrain: grass_diagonal_crossing finds where the ground's diagonal crosses a vertical plane, "
          "in every mirror") {
    // The ground's two triangles meet along world-order cell points with x + z = 1 (height_field.h).
    for (const glm::vec2 mirror : {glm::vec2(1, 1), glm::vec2(-1, 1), glm::vec2(1, -1), glm::vec2(-1, -1)})
        for (int axis = 0; axis < 2; ++axis)
            for (float plane : {0.0f, 0.1f, 0.5f, 0.73f, 1.0f}) {
                CAPTURE(mirror);
                CAPTURE(axis);
                CAPTURE(plane);
                const float other = shader::grass_diagonal_crossing(axis, plane, mirror);
                const glm::vec2 patch_xz = axis == 0 ? glm::vec2(plane, other) : glm::vec2(other, plane);
                const glm::vec2 cell = shader::grass_cell_point(patch_xz, mirror);
                CHECK(cell.x + cell.y == doctest::Approx(1.0f).epsilon(1e-6));
                CHECK(other >= 0.0f);
                CHECK(other <= 1.0f);
            }
}
