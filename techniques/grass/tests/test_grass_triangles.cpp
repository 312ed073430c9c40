// The triangles each grass representation's frame submits and rasterises (Vulkan pipeline
// statistics, FrameRenderer::render_counting_primitives), as Lemme's Table 7.1 counts them: the
// blades' every triangle; the volume's 12 a cuboid submitted, of which only the faces a ray leaves
// by (at most 3, 6 triangles) survive clipping, so Lemme's "6144" for 1024 cells; the image's 2 a
// cell. Drawing the faces a ray enters by (Lemme's front faces as well as canopy's back faces)
// fails the volume's bound. How many triangles clipping outputs for one it cuts is the
// implementation's choice (the Vulkan spec: "one or more"; lavapipe splits a few), hence the slack.
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"
#include "scene/geometry.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <map>
#include <string>

using namespace canopy;

namespace {

constexpr uint64_t kCells = 3 * 2, kBlades = 60, kTrianglesPerBlade = 8;  // subdivisions = 3

// A 3 x 2 field seen whole from above and aside, no other object.
Scene field() {
    return parse_scene(R"([scene]
name = "counted"
[camera]
position = [1.0, 4.0, 5.0]
target = [0.0, 0.0, 0.0]
fov = 50
[[light]]
type = "directional"
direction = [-0.3, -1, -0.2]
casts_shadows = false
[[population]]
name = "lawn"
kind = "grass"
params = { cells_x = 3, cells_z = 2, blades = 60, subdivisions = 3 }
)",
                       "counted.toml");
}

PrimitiveCounts counted(const std::string& technique_name, const std::map<std::string, ParamValue>& values = {}) {
    const Technique* technique = TechniqueRegistry::instance().find(technique_name);
    REQUIRE(technique);
    const Scene scene = field();
    const ParamSet params = ParamSet::resolve(technique->params(), values, {}, {}, technique_name);
    FrameRenderer renderer(test::gpu(), scene, build_scene_meshes(scene), 160, 120, technique->graph(params));
    REQUIRE(test::gpu().pipeline_statistics());
    CHECK_FALSE(renderer.render().primitives.has_value());  // timed frames are not counted
    const FrameTiming t = renderer.render_counting_primitives(FrameState{1, scene.camera});
    REQUIRE(t.primitives.has_value());
    return *t.primitives;
}

}  // namespace

TEST_CASE("grass triangles: the blades submit all theirs and rasterise what clipping keeps") {
    const PrimitiveCounts c = counted("grass.geometry");
    CHECK(c.submitted == kCells * kBlades * kTrianglesPerBlade);
    CHECK(c.rasterised <= c.submitted + c.submitted / 100);
    CHECK(c.rasterised >= c.submitted * 9 / 10);  // the whole field is in view
}

TEST_CASE("grass triangles: a volume cuboid submits 12 and rasterises only the faces a ray leaves by") {
    const PrimitiveCounts c = counted("grass.volume", {{"slices", 2LL}, {"resolution", 32LL}, {"height_resolution", 8LL}});
    CHECK(c.submitted == kCells * 12);
    CHECK(c.rasterised <= kCells * 6 * 5 / 4);  // the 12 a cuboid would be 72 here
    CHECK(c.rasterised >= kCells * 2);
}

TEST_CASE("grass triangles: the image draws one quad a cell") {
    const PrimitiveCounts c = counted("grass.image", {{"resolution", 32LL}});
    CHECK(c.submitted == kCells * 2);
    CHECK(c.rasterised >= kCells * 2);
    CHECK(c.rasterised <= kCells * 2 * 5 / 4);
}
