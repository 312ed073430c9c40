// Scene populations (scene/population.hpp, issue 9): the deterministic generator, [[population]]
// tables and their file:line errors, the reference's instanced copies (camera and shadow rays),
// the reference cache key, and the refusal of techniques that render no populations.
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "reference/embree_scene.hpp"
#include "reference/reference_cache.hpp"
#include "render/frame_renderer.hpp"
#include "scene/generated_population.hpp"
#include "scene/geometry.hpp"
#include "scene/population.hpp"
#include "support/config_error_of.hpp"
#include "support/reference_hits.hpp"
#include "support/test_gpu.hpp"
#include "support/text_search.hpp"

#include "alpha_mask.h"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

using namespace canopy;
using test::config_error_of;
using test::contains;

namespace {

// The copies generate_instances returns, by value (a scatter population's are owned by the result alone).
std::vector<PopulationInstance> instances_of(const Population& population) { return *generate_instances(population); }

// A floor with a population of small boxes on it; `population_lines` replaces the population's keys.
const std::string kHeader = "[scene]\nname = \"meadow\"\n"
                            "[camera]\nposition = [0, 6, 4]\ntarget = [0, 0, 0]\n"
                            "[[light]]\ntype = \"directional\"\ndirection = [0, -1, 0]\n"
                            "[[object]]\nname = \"floor\"\nshape = \"plane\"\nsize = [8, 8]\n";
const std::string kPopulation = "[[population]]\n"  // line 13
                                "name = \"pebbles\"\n"
                                "kind = \"scatter\"\n"
                                "count = 50\n"
                                "region_min = [-2, -1.5]\n"
                                "region_max = [2, 1.5]\n"
                                "ground = 0.0\n"
                                "seed = 7\n"
                                "scale = [0.5, 1.5]\n"
                                "prototype = { shape = \"box\", size = 0.2, translate = [0, 0.1, 0], albedo = [0.9, 0.2, 0.1] }\n";

Scene meadow(const std::string& population = kPopulation) { return parse_scene(kHeader + population, "meadow.toml"); }

std::string replace_line(const std::string& text, const std::string& key, const std::string& line) {
    const size_t start = text.find("\n" + key + " ") + 1;
    REQUIRE(start != 0);
    const size_t end = text.find('\n', start);
    return text.substr(0, start) + line + text.substr(end);
}

std::optional<ConfigError> population_error(const std::string& population) {
    return config_error_of([&] { meadow(population); });
}

}  // namespace

TEST_CASE("population: a [[population]] table loads with every key") {
    const Scene scene = meadow();
    REQUIRE(scene.populations.size() == 1);
    const Population& p = scene.populations[0];
    CHECK(p.name == "pebbles");
    CHECK(p.kind == population_kinds::kScatter);
    CHECK(p.count == 50);
    CHECK(p.region_min == glm::vec2(-2.0f, -1.5f));
    CHECK(p.region_max == glm::vec2(2.0f, 1.5f));
    CHECK(p.seed == 7);
    CHECK(p.scale_min == 0.5f);
    CHECK(p.scale_max == 1.5f);
    CHECK(p.random_yaw);
    CHECK(p.prototype.shape == ShapeType::box);
    CHECK(p.prototype.box_size == glm::vec3(0.2f));
    CHECK(p.prototype.material.albedo == glm::vec3(0.9f, 0.2f, 0.1f));
    REQUIRE(p.prototype.instances.size() == 1);
    CHECK(p.prototype.instances[0].translate == glm::vec3(0.0f, 0.1f, 0.0f));
    CHECK(p.where.line == 13);
    CHECK(scene.objects.size() == 1);  // the population is not an object
}

TEST_CASE("population: an alpha mask loads, reaches every copy and cuts what alpha_mask.h says") {
    const Scene scene =
        meadow(kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"z\", period = 0.25, opaque = 0.4 }\n");
    const AlphaMask& mask = scene.populations[0].alpha_mask;
    CHECK(mask.kind == AlphaMask::Kind::stripes);
    CHECK(mask.axis == 2);
    CHECK(mask.period == 0.25f);
    CHECK(mask.opaque == 0.4f);
    CHECK(meadow().populations[0].alpha_mask.kind == AlphaMask::Kind::none);  // none unless asked
    for (const PopulationInstance& copy : instances_of(scene.populations[0]))
        CHECK(copy.data == glm::vec4(shader::ALPHA_MASK_STRIPES, 2.0f, 0.25f, 0.4f));

    // The function the fragment shader and the reference's filter both call.
    const glm::vec4 packed = mask.packed();
    using shader::alpha_mask_opaque;
    CHECK(alpha_mask_opaque(packed, glm::vec3(9.0f, 9.0f, 0.05f)));    // 0.2 of the period: stays
    CHECK(!alpha_mask_opaque(packed, glm::vec3(0.0f, 0.0f, 0.15f)));   // 0.6: cut
    CHECK(alpha_mask_opaque(packed, glm::vec3(0.0f, 0.0f, -0.2f)));    // -0.8 -> phase 0.2: stays
    CHECK(!alpha_mask_opaque(packed, glm::vec3(0.0f, 0.0f, -0.1f)));   // phase 0.6: cut
    CHECK(shader::alpha_mask_period_index(packed, glm::vec3(0.0f, 0.0f, -0.1f)) == -1.0f);
    CHECK(alpha_mask_opaque(glm::vec4(0.0f), glm::vec3(0.3f)));  // no mask: opaque everywhere
    AlphaMask solid = mask;
    solid.opaque = 1.0f;  // the extreme the config allows: nothing is cut
    for (float z = -3.0f; z <= 3.0f; z += 0.0137f) CHECK(alpha_mask_opaque(solid.packed(), glm::vec3(0.0f, 0.0f, z)));
    // The smallest period the config allows still cuts at far coordinates, finitely.
    const glm::vec4 fine(shader::ALPHA_MASK_STRIPES, 0.0f, 1e-3f, 0.5f);
    int cut = 0;
    for (int i = 0; i < 1000; ++i) cut += !alpha_mask_opaque(fine, glm::vec3(100.0f + float(i) * 1.37e-4f, 0.0f, 0.0f));
    CHECK(cut > 300);
    CHECK(cut < 700);
}

TEST_CASE("population: the generator is deterministic, stays in its region and ranges, and copy k ignores count") {
    const Population p = meadow().populations[0];
    const std::vector<PopulationInstance> a = instances_of(p), b = instances_of(p);
    REQUIRE(a.size() == 50);
    std::set<float> yaws_cos, scales;
    for (size_t i = 0; i < a.size(); ++i) {
        CAPTURE(i);
        CHECK(std::memcmp(&a[i], &b[i], sizeof(PopulationInstance)) == 0);
        const glm::mat4 placement = scatter_placement(p, uint32_t(i));
        CHECK(placement[3].x >= -2.0f);
        CHECK(placement[3].x <= 2.0f);
        CHECK(placement[3].z >= -1.5f);
        CHECK(placement[3].z <= 1.5f);
        CHECK(placement[3].y == 0.0f);
        const float scale = placement[1].y;  // uniform: the y axis is only scaled
        CHECK(scale >= 0.5f);
        CHECK(scale <= 1.5f);
        CHECK(glm::length(glm::vec3(placement[0])) == doctest::Approx(scale).epsilon(1e-5));
        // The prototype's own transform first: its bottom (local y = -0.1 + 0.1) sits on the ground.
        CHECK(glm::vec3(a[i].model * glm::vec4(0, -0.1f, 0, 1)).y == doctest::Approx(0.0).epsilon(1e-6));
        yaws_cos.insert(placement[0].x / scale);
        scales.insert(scale);
    }
    CHECK(yaws_cos.size() > 45);  // random yaws and scales, not one repeated
    CHECK(scales.size() > 45);

    Population fewer = p;
    fewer.count = 20;
    const std::vector<PopulationInstance> c = instances_of(fewer);
    REQUIRE(c.size() == 20);
    for (size_t i = 0; i < c.size(); ++i) CHECK(std::memcmp(&a[i], &c[i], sizeof(PopulationInstance)) == 0);

    Population reseeded = p;
    reseeded.seed = 8;
    const std::vector<PopulationInstance> d = instances_of(reseeded);
    int moved = 0;
    for (size_t i = 0; i < d.size(); ++i) moved += d[i].model[3] != a[i].model[3];
    CHECK(moved == 50);

    Population upright = p;
    upright.random_yaw = false;
    for (const PopulationInstance& copy : instances_of(upright)) CHECK(copy.model[0].z == 0.0f);
}

TEST_CASE("population: the copies cover their region evenly") {
    Population p = meadow().populations[0];
    p.count = 40000;
    p.region_min = glm::vec2(0.0f);
    p.region_max = glm::vec2(1.0f);
    int cells[4][4] = {};
    for (uint32_t i = 0; i < p.count; ++i) {
        const glm::mat4 m = scatter_placement(p, i);
        cells[std::min(3, int(m[3].x * 4))][std::min(3, int(m[3].z * 4))]++;
    }
    for (auto& row : cells)
        for (int n : row) CHECK(std::abs(n - 2500) < 250);  // about 5 standard deviations
}

TEST_CASE("population: every mistake in a [[population]] is reported at its line with a hint") {
    struct Case {
        std::string population;
        int line;
        std::string message, hint;
    };
    const std::vector<Case> cases{
        {replace_line(kPopulation, "kind", "kind = \"scater\""), 15, "unknown population kind 'scater'", "did you mean 'scatter'?"},
        {replace_line(kPopulation, "count", "count = 0"), 16, "'count' in [[population]] #1 must lie in [1, 1000000], got 0", "one Embree instance per copy"},
        {replace_line(kPopulation, "count", "count = 1000001"), 16, "must lie in [1, 1000000]", ""},
        {replace_line(kPopulation, "count", "count = 2.5"), 16, "count", ""},
        {replace_line(kPopulation, "count", "cuont = 5"), 16, "cuont", "count"},
        {replace_line(kPopulation, "region_max", "region_max = [-3, 1.5]"), 18, "must exceed 'region_min'", "smaller x and z"},
        {replace_line(kPopulation, "region_min", "region_min = [-2e6, 0]"), 17, "outside the scene's coordinate range", "1e6"},
        {replace_line(kPopulation, "ground", "ground = 3e6"), 19, "outside the scene's coordinate range", ""},
        {replace_line(kPopulation, "seed", "seed = -1"), 20, "must not be negative", "seed = 7"},
        {replace_line(kPopulation, "scale", "scale = [2, 1]"), 21, "min exceeds max", "[min, max]"},
        {replace_line(kPopulation, "scale", "scale = [0, 1]"), 21, "must lie in [0.001, 1000]", ""},
        {replace_line(kPopulation, "seed", "sead = 7"), 20, "sead", "seed"},
        {replace_line(kPopulation, "prototype", "prototyp = { shape = \"box\" }"), 22, "prototyp", "prototype"},
        {replace_line(kPopulation, "region_max", "region_max = 2"), 18, "region_max", ""},
        {replace_line(kPopulation, "prototype", "prototype = { shape = \"box\", instances = [{ translate = [1, 0, 0] }] }"),
         22, "has no 'instances'", "the population places the copies"},
        {replace_line(kPopulation, "prototype", "prototype = { shape = \"box\", name = \"x\" }"), 22, "has no 'name'", ""},
        {replace_line(kPopulation, "prototype", "prototype = { shape = \"box\", radius = 1 }"), 22, "radius", ""},
        {replace_line(kPopulation, "prototype", "prototype = { shape = \"box\", colour = 1 }"), 22, "colour", ""},
        // alpha_mask = { ... } on the line after the prototype (line 23).
        {kPopulation + "alpha_mask = { kind = \"stripe\", axis = \"x\", period = 0.1 }\n", 23,
         "unknown alpha mask kind 'stripe'", "did you mean 'stripes'?"},
        {kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"w\", period = 0.1 }\n", 23, "unknown axis 'w'", "x, y, z"},
        {kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"x\" }\n", 23, "needs a 'period'", "period = 0.1"},
        {kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"x\", period = 0 }\n", 23,
         "'period' in alpha_mask of [[population]] #1 must lie in [0.001, 1000], got 0", ""},
        {kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"x\", period = 0.1, opaque = 0 }\n", 23,
         "must lie in (0, 1], got 0", "1 cuts nothing"},
        {kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"x\", period = 0.1, opaqe = 0.5 }\n", 23, "opaqe",
         "opaque"},
    };
    for (const Case& c : cases) {
        CAPTURE(c.population);
        const auto error = population_error(c.population);
        REQUIRE(error);
        INFO(error->formatted());
        CHECK(error->file() == "meadow.toml");
        CHECK(error->line() == c.line);
        CHECK(contains(error->what(), c.message));
        CHECK(contains(error->hint(), c.hint));
    }
    // A missing prototype or region names the population's table.
    for (const char* key : {"prototype", "region_min"}) {
        CAPTURE(key);
        std::string population = kPopulation;
        const size_t start = population.find(std::string(key) + " ");
        population.erase(start, population.find('\n', start) + 1 - start);
        const auto error = population_error(population);
        REQUIRE(error);
        CHECK(error->line() == 13);
        CHECK(contains(error->what(), std::string("needs ")));
    }
}

TEST_CASE("population: prototype meshes follow the objects', and copies stay within the limits") {
    const Scene scene = meadow();
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    REQUIRE(meshes.size() == 2);
    CHECK(prototype_mesh(scene, meshes, 0).triangle_count() == 12);  // a box
    CHECK(meshes[0].triangle_count() == 2);                          // the floor
    // The scene's bounds hold every copy (e.g. for a light view).
    const Bounds bounds = scene_bounds(scene, meshes);
    for (const PopulationInstance& copy : instances_of(scene.populations[0]))
        CHECK(glm::vec3(copy.model[3]).y >= bounds.min.y);

    // 1e6 copies of a 960-triangle sphere (1e9 triangles) are fine: the reference stores the
    // prototype once and instances it per copy.
    const Scene many = meadow(replace_line(replace_line(kPopulation, "count", "count = 1000000"), "prototype",
                                           "prototype = { shape = \"sphere\", radius = 0.1 }"));
    CHECK(build_scene_meshes(many).back().triangle_count() == 960);

    // A region at the edge of the coordinate range with a large prototype reaches outside it.
    const auto outside = config_error_of([] {
        build_scene_meshes(meadow(replace_line(replace_line(kPopulation, "region_max", "region_max = [1e6, 1.5]"),
                                               "scale", "scale = [500, 1000]")));
    });
    REQUIRE(outside);
    CHECK(outside->line() == 13);
    CHECK(contains(outside->what(), "outside the scene's coordinate range"));
}

TEST_CASE("population: the reference traces every copy, for camera and shadow rays") {
    const Scene scene = meadow();
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    const EmbreeScene embree(scene, meshes);
    CHECK(embree.triangle_count() == 2 + 50 * 12);
    CHECK(embree.stored_triangle_count() == 2 + 12);  // the prototype once, instanced per copy
    REQUIRE(embree.geometry_count() == 2);
    CHECK(embree.geometry(1).population == 0);
    CHECK(embree.geometry(1).prototype_triangles == 12);
    CHECK(embree.material(1).albedo == glm::vec3(0.9f, 0.2f, 0.1f));

    const std::vector<PopulationInstance> copies = instances_of(scene.populations[0]);
    int hits = 0, occluded = 0, right_copy = 0, upright = 0;
    for (size_t k = 0; k < copies.size(); ++k) {
        // The centre of the copy's top face: the box's local top (y = 0.1), lifted by its own translate.
        const glm::vec3 top = glm::vec3(copies[k].model * glm::vec4(0.0f, 0.1f, 0.0f, 1.0f));
        const RTCRayHit ray = test::trace_down(embree, top.x, top.z, 5.0f, 10.0f);
        const EmbreeHit hit = ray.hit.geomID == RTC_INVALID_GEOMETRY_ID ? EmbreeHit{} : embree.resolve(ray.hit);
        if (hit.geometry == 1) {
            ++hits;
            // The hit lies on some copy's top; copies may overlap, so it is this one or a taller one.
            if (hit.primitive / 12 == k || 5.0f - ray.ray.tfar > top.y + 1e-4f) ++right_copy;
            // The top face's normals in world space, whatever the copy's yaw and scale.
            const glm::vec3 normal = glm::normalize(hit.geometric_normal);
            upright += std::abs(normal.y) > 0.9999f &&
                       embree.shading_normal(hit.geometry, hit.primitive, ray.hit.u, ray.hit.v).y > 0.9999f;
        }
        RTCRay shadow{};
        shadow.org_x = top.x;
        shadow.org_y = 5.0f;
        shadow.org_z = top.z;
        shadow.dir_y = -1.0f;
        shadow.tfar = 5.0f - 0.5f * top.y;  // stops above the floor, inside the copy's height
        shadow.mask = 0xffffffffu;
        RTCIntersectContext context{};
        rtcInitIntersectContext(&context);
        rtcOccluded1(embree.shadow_scene(), &context, &shadow);
        occluded += shadow.tfar < 0.0f;  // Embree marks an occluded ray with tfar = -inf
    }
    CHECK(hits == 50);
    CHECK(right_copy == 50);
    CHECK(upright == 50);
    CHECK(occluded == 50);

    // A population that casts no shadows is in the camera's scene only.
    Scene unshadowed = scene;
    unshadowed.populations[0].prototype.casts_shadows = false;
    const EmbreeScene without(unshadowed, meshes);
    CHECK(without.shadow_scene() != without.visible_scene());
}

TEST_CASE("population: the reference cache key covers every population setting") {
    const Scene scene = meadow();
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    const ReferenceSettings settings;
    const std::string key = reference_cache_key(scene, meshes, 64, 48, settings);
    CHECK(reference_cache_key(meadow(), build_scene_meshes(meadow()), 64, 48, settings) == key);
    const auto key_with = [&](auto change) {
        Scene changed = scene;
        change(changed.populations[0]);
        return reference_cache_key(changed, build_scene_meshes(changed), 64, 48, settings);
    };
    std::set<std::string> keys{key};
    keys.insert(key_with([](Population& p) { p.seed = 8; }));
    keys.insert(key_with([](Population& p) { p.count = 49; }));
    keys.insert(key_with([](Population& p) { p.region_max.x = 2.5f; }));
    keys.insert(key_with([](Population& p) { p.ground_y = 0.01f; }));
    keys.insert(key_with([](Population& p) { p.scale_max = 1.4f; }));
    keys.insert(key_with([](Population& p) { p.random_yaw = false; }));
    keys.insert(key_with([](Population& p) { p.prototype.material.albedo.x = 0.5f; }));
    keys.insert(key_with([](Population& p) { p.prototype.casts_shadows = false; }));
    keys.insert(key_with([](Population& p) { p.prototype.box_size = glm::vec3(0.3f); }));
    keys.insert(key_with([](Population& p) { p.prototype.instances[0].translate.y = 0.2f; }));
    keys.insert(key_with([](Population& p) { p.alpha_mask.kind = AlphaMask::Kind::stripes; }));
    keys.insert(key_with([](Population& p) {
        p.alpha_mask.kind = AlphaMask::Kind::stripes;
        p.alpha_mask.opaque = 0.5f;
    }));
    CHECK(keys.size() == 13);
    // A scene without the population has yet another key.
    Scene bare = scene;
    bare.populations.clear();
    CHECK(keys.count(reference_cache_key(bare, build_scene_meshes(bare), 64, 48, settings)) == 0);
}

TEST_CASE("population: a technique that does not declare a population's kind is refused on its scene") {
    const Scene scene = meadow();
    int refused = 0;
    for (const Technique* technique : TechniqueRegistry::instance().all()) {
        CAPTURE(technique->name());
        const FrameGraph graph = technique->graph(ParamSet::resolve(technique->params(), {}, {}, {}, technique->name()));
        if (!graph.needs.populations.empty()) continue;
        const auto why = check_supported(test::gpu(), scene, graph);
        REQUIRE(why);
        CHECK(contains(why->reason, "scene 'meadow'"));
        CHECK(contains(why->reason, "population 'pebbles'"));
        CHECK(contains(why->reason, "kind 'scatter'"));
        CHECK(contains(why->reason, "it renders no populations"));
        CHECK(contains(why->hint, "meadow.toml:13"));
        CHECK(contains(why->hint, "remove the [[population]]"));
        ++refused;
        // The same scene without the population is not refused for it.
        Scene bare = scene;
        bare.populations.clear();
        const auto bare_why = check_supported(test::gpu(), bare, graph);
        CHECK((!bare_why || !contains(bare_why->reason, "population")));
    }
    CHECK(refused >= 10);  // every shadow technique
    // A graph that declares another kind is refused too, naming what it renders.
    FrameGraph other;
    other.needs.populations = {"forest"};
    const auto why = check_supported(test::gpu(), scene, other);
    REQUIRE(why);
    CHECK(contains(why->reason, "it renders 'forest' populations"));
}

TEST_CASE("population: generate_populations hands the raster side the declared kinds only") {
    const Scene scene = meadow();
    const std::vector<TriangleMesh> meshes = build_scene_meshes(scene);
    CHECK(generate_populations(scene, meshes, {}).empty());
    CHECK(generate_populations(scene, meshes, {"forest"}).empty());
    const std::vector<GeneratedPopulation> generated = generate_populations(scene, meshes, {"scatter"});
    REQUIRE(generated.size() == 1);
    CHECK(generated[0].name == "pebbles");
    CHECK(generated[0].prototype.triangle_count() == 12);
    REQUIRE(generated[0].instances.size() == 50);
    CHECK(std::memcmp(generated[0].instances.data(), generate_instances(scene.populations[0])->data(),
                      50 * sizeof(PopulationInstance)) == 0);
}

TEST_CASE("population: the reference traces shadow rays one at a time where instanced copies are cut, in packets elsewhere") {
    // shadow_packet.hpp: Embree's 16-wide occlusion kernel was seen to hang on instanced copies
    // with a filter function.
    const Scene masked = meadow(kPopulation + "alpha_mask = { kind = \"stripes\", axis = \"z\", period = 0.25, opaque = 0.4 }\n");
    const Scene opaque = meadow();
    const Scene without = parse_scene(kHeader, "plain.toml");
    CHECK(EmbreeScene(masked, build_scene_meshes(masked)).shadow_query() == ShadowQuery::single);
    CHECK(EmbreeScene(opaque, build_scene_meshes(opaque)).shadow_query() == ShadowQuery::packet16);
    CHECK(EmbreeScene(without, build_scene_meshes(without)).shadow_query() == ShadowQuery::packet16);

    // One ray at a time answers as the packet does: rays up from the floor through the striped
    // pebbles, on a grid over their region, some through a stripe and some blocked.
    const EmbreeScene embree(masked, build_scene_meshes(masked));
    EmbreeShadowTracer packets(embree.shadow_scene(), ShadowQuery::packet16);
    EmbreeShadowTracer singles(embree.shadow_scene(), ShadowQuery::single);
    int occluded = 0, traced = 0;
    for (int row = 0; row < 60; ++row) {
        ShadowPacket a, b;
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            const glm::vec3 origin(-2.0f + 4.0f * (float(lane) + 0.5f) / 16.0f, 0.001f, -1.5f + 3.0f * (float(row) + 0.5f) / 60.0f);
            const bool trace = (lane + row) % 5 != 0;  // some lanes left out
            a.set(lane, origin, glm::vec3(0.0f, 1.0f, 0.0f), 10.0f, trace);
            b.set(lane, origin, glm::vec3(0.0f, 1.0f, 0.0f), 10.0f, trace);
        }
        packets.trace(a);
        singles.trace(b);
        for (int lane = 0; lane < ShadowPacket::kWidth; ++lane) {
            CHECK(a.occluded(lane) == b.occluded(lane));
            occluded += a.occluded(lane);
            traced += a.valid[lane] != 0;
        }
    }
    CHECK(singles.rays() == packets.rays());
    CHECK(occluded > 20);
    CHECK(occluded < traced);
}
