// grass.geometry's GPU cull (culling = "gpu"): a compute pass keeps the copies whose box may be
// seen and writes the indirect draw's instance count. The culled frame is the unculled frame,
// pixel for pixel; the count is the number of cells a CPU test of the same boxes keeps (box
// corners projected one by one, written apart from the shader's header), fewer than the field
// has; with max_distance, cells beyond it are gone and the rest unchanged. A box shrunk, a plane
// dropped or the count not reset each frame fails a check here.
#include "support/bake_truth.hpp"
#include "support/cpu_checks.hpp"

#include "../common/grass_population.hpp"

#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/camera.hpp"
#include "scene/geometry.hpp"
#include "scene/population_kind.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <cstring>
#include <map>
#include <string>
#include <vector>

using namespace canopy;

namespace {

constexpr uint32_t kWidth = 160, kHeight = 100;

// An 8 x 8 field seen from one corner, looking along it: part of it is outside the view.
Scene field_scene() {
    return parse_scene(
        "[scene]\nname = \"cull\"\nambient = 0.2\n"
        "[camera]\nposition = [-4.5, 1.2, -4.5]\ntarget = [0, 0, -1.5]\nfov = 25\n"
        "[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n"
        "[[object]]\nname = \"ground\"\nshape = \"plane\"\nsize = [10, 10]\nalbedo = [0.6, 0.3, 0.1]\n"
        "[[population]]\nname = \"field\"\nkind = \"grass\"\nalbedo = [0.1, 0.8, 0.1]\n"
        "params = { cells_x = 8, cells_z = 8, blades = 60, subdivisions = 2, width_min = 0.04, width_max = 0.06 }\n",
        "cull.toml");
}

// The same field on steep hills (one grid quad a cell), seen from low down: cells whose first
// corner lies below the view show blades lifted into it by their other corners.
Scene hilly_field_scene() {
    return parse_scene(
        "[scene]\nname = \"cull-hills\"\nambient = 0.2\n"
        "[camera]\nposition = [-4.5, 1.0, -4.5]\ntarget = [0, 1.6, 0]\nfov = 25\n"
        "[[light]]\ntype = \"directional\"\ndirection = [-0.3, -1, -0.2]\ncasts_shadows = false\n"
        "[[object]]\nname = \"ground\"\nshape = \"heightfield\"\nsize = [8, 8]\nvertices = 9\nperiods = 2\n"
        "height_scale = 3\nalbedo = [0.6, 0.3, 0.1]\n"
        "[[population]]\nname = \"field\"\nkind = \"grass\"\nterrain = \"ground\"\nalbedo = [0.1, 0.8, 0.1]\n"
        "params = { cells_x = 8, cells_z = 8, blades = 60, subdivisions = 2, width_min = 0.04, width_max = 0.06 }\n",
        "cull-hills.toml");
}

struct Culled {
    Image image;
    uint32_t instances = 0;  // the indirect draw's instance count, as the cull wrote it
};

Culled render(const Scene& scene, const std::map<std::string, ParamValue>& params, int frames = 1) {
    const Technique* t = TechniqueRegistry::instance().find("grass.geometry");
    REQUIRE(t);
    std::map<std::string, ParamValue> p = params;
    p["samples"] = 1LL;
    p["coverage"] = std::string("alpha_test");
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), kWidth, kHeight,
                           t->graph(ParamSet::resolve(t->params(), p, {}, {}, "grass.geometry")));
    for (int f = 0; f < frames; ++f) renderer.render();
    Culled c{renderer.read_color()};
    if (params.count("culling") && std::get<std::string>(params.at("culling")) == "gpu") {
        const std::vector<std::byte> bytes = renderer.read_buffer("draw_arguments");
        REQUIRE(bytes.size() >= sizeof(VkDrawIndexedIndirectCommand));
        VkDrawIndexedIndirectCommand arguments;
        std::memcpy(&arguments, bytes.data(), sizeof(arguments));
        c.instances = arguments.instanceCount;
    }
    return c;
}

int differing_pixels(const Image& a, const Image& b) {
    int n = 0;
    for (size_t i = 0; i < a.pixels.size(); i += 4)
        n += std::abs(a.pixels[i] - b.pixels[i]) > 1e-6f || std::abs(a.pixels[i + 1] - b.pixels[i + 1]) > 1e-6f ||
             std::abs(a.pixels[i + 2] - b.pixels[i + 2]) > 1e-6f;
    return n;
}

// The CPU's count: cells whose box (the prototype's bounds through the copy's matrix) has a
// corner inside the clip volume or straddles it, i.e. not all 8 corners beyond one clip plane;
// and, with a limit, whose nearest world-box point is within it.
int expected_cells(const Scene& scene, float max_distance) {
    const Population& population = scene.populations.at(0);
    Bounds box;
    for (const Vertex& v : population.family->prototype.vertices) box.extend(v.position);
    const Camera& camera = scene.camera;
    const glm::mat4 view_proj = projection_matrix(camera, float(kWidth) / float(kHeight)) * view_matrix(camera);
    int kept = 0;
    const auto copies = generate_instances(population);
    for (const PopulationInstance& copy : *copies) {
        std::array<glm::vec3, 8> corners;
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (int c = 0; c < 8; ++c) {
            const glm::vec3 corner((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                   (c & 4) ? box.max.z : box.min.z);
            corners[size_t(c)] = glm::vec3(copy.model * glm::vec4(corner, 1.0f));
            lo = glm::min(lo, corners[size_t(c)]);
            hi = glm::max(hi, corners[size_t(c)]);
        }
        bool seen = grass::test::corners_may_be_seen(view_proj, corners);
        if (seen && max_distance > 0.0f) seen = glm::length(camera.position - glm::clamp(camera.position, lo, hi)) <= max_distance;
        kept += seen;
    }
    return kept;
}

}  // namespace

TEST_CASE("grass.geometry culling: the culled frame is the whole field's, drawn from fewer copies") {
    const Scene scene = field_scene();
    const Culled whole = render(scene, {});
    const Culled culled = render(scene, {{"culling", std::string("gpu")}}, 3);  // the count restarts every frame
    const int expected = expected_cells(scene, 0.0f);
    CAPTURE(expected);
    CHECK(expected > 8);
    CHECK(expected < 56);  // the view leaves some of the 64 cells out
    CHECK(culled.instances == uint32_t(expected));
    CHECK(grass::test::grass_pixels(whole.image) > int(kWidth * kHeight) / 20);
    CHECK(differing_pixels(whole.image, culled.image) == 0);
}

TEST_CASE("grass.geometry culling on a terrain: a cell's box rises with its ground, so nothing in view is culled") {
    const Scene scene = hilly_field_scene();
    const Culled whole = render(scene, {});
    const Culled culled = render(scene, {{"culling", std::string("gpu")}});
    CAPTURE(culled.instances);
    CHECK(culled.instances < 64);
    CHECK(grass::test::grass_pixels(whole.image) > int(kWidth * kHeight) / 20);
    CHECK(differing_pixels(whole.image, culled.image) == 0);
}

TEST_CASE("grass.geometry culling: beyond max_distance no copy is drawn, nearer ones as before") {
    const Scene scene = field_scene();
    const float limit = 5.0f;
    const Culled whole = render(scene, {});
    const Culled near = render(scene, {{"culling", std::string("gpu")}, {"max_distance", double(limit)}});
    const int expected = expected_cells(scene, limit);
    CAPTURE(expected);
    CHECK(expected > 2);
    CHECK(expected < expected_cells(scene, 0.0f));
    CHECK(near.instances == uint32_t(expected));
    // Far grass is gone, near grass is the same: compare by the pixels' distance along the view.
    const int lost = grass::test::grass_pixels(whole.image) - grass::test::grass_pixels(near.image);
    CAPTURE(lost);
    CHECK(lost > 100);
    for (float v : near.image.pixels) REQUIRE(std::isfinite(v));
}
