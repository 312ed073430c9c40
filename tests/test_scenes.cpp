// Every technique renders every committed paper scene (configs/scenes) without a NaN, Inf or
// negative pixel: the acceptance check of issue 4 at a small resolution.
#include "config/scene_config.hpp"
#include "core/registry.hpp"
#include "render/frame_renderer.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;

namespace {

GpuContext& gpu() {
    static GpuContext context;
    return context;
}

void check_scene(const std::string& name) {
    const Scene scene = load_scene(std::string(CANOPY_SOURCE_DIR) + "/configs/scenes/" + name + ".toml");
    const auto meshes = build_scene_meshes(scene);
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        CAPTURE(name);
        const std::string technique = t->name();
        CAPTURE(technique);
        const ParamSet params = ParamSet::resolve(t->params(), {}, {}, {}, technique);
        FrameRenderer renderer(gpu(), scene, meshes, 160, 90, t->plan(params));
        renderer.render();
        const Image image = renderer.read_color();
        long long nonfinite = 0, negative = 0;
        for (float v : image.pixels) {
            nonfinite += std::isfinite(v) ? 0 : 1;
            negative += v < 0.0f ? 1 : 0;
        }
        CHECK_MESSAGE(nonfinite == 0, "NaN/Inf channel values: ", nonfinite);
        CHECK(negative == 0);
    }
}

}  // namespace

TEST_CASE("spheres renders with every technique") { check_scene("spheres"); }
TEST_CASE("chairs renders with every technique") { check_scene("chairs"); }
TEST_CASE("car renders with every technique") { check_scene("car"); }
TEST_CASE("at-at renders with every technique") { check_scene("at-at"); }
