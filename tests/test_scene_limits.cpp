// Scene values outside the ranges where the renderers' single-precision math stays finite and
// precise (scene/scene_limits.hpp, configs/README.md "Limits") are refused when the scene is
// loaded, at the offending line, before anything is rendered or written.
#include "config/scene_config.hpp"
#include "core/error.hpp"
#include "scene/geometry.hpp"
#include "scene/scene_limits.hpp"
#include "support/config_error_of.hpp"
#include "support/text_search.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;
using test::config_error_of;
using test::contains;

namespace {

const std::string kLight = "[[light]]\ntype = \"directional\"\n";  // lines 1-2
const std::string kBox = "[[object]]\nshape = \"box\"\n";

// The line of the error parse_scene raises for `text`, -1 when it loads; the message must
// mention `words`.
int error_line(const std::string& text, const std::string& words = "") {
    const auto error = config_error_of([&] { parse_scene(text, "s.toml"); });
    if (!error) return -1;
    INFO(error->formatted());
    CHECK(contains(error->what(), words));
    return error->line();
}

}  // namespace

TEST_CASE("light values that overflow the reference's float math are refused at their line") {
    // Before: 1e39 became infinity in a float and failed at reference time, after files were
    // written; 3e38 rendered with a PSNR of -696 dB.
    CHECK(error_line(kLight + "intensity = 1e39\n", "single-precision") == 3);
    CHECK(error_line(kLight + "intensity = 3e38\n", "intensity") == 3);
    CHECK(error_line(kLight + "intensity = 1000001\n", "intensity") == 3);
    CHECK(error_line(kLight + "intensity = 1e6\n") == -1);
    CHECK(error_line(kLight + "intensity = 0\n") == -1);
    CHECK(error_line(kLight + "color = 101\n", "color") == 3);
    CHECK(error_line(kLight + "color = [1, 100, 0.5]\n") == -1);
    const std::string rect = "[[light]]\ntype = \"rect\"\nup = [0, 0, 1]\n";
    CHECK(error_line(rect + "size = [1e-5, 1]\n", "size") == 4);
    CHECK(error_line(rect + "size = [1, 2e4]\n", "size") == 4);
    CHECK(error_line(rect + "size = [1e-4, 1e4]\n") == -1);
    const std::string sphere = "[[light]]\ntype = \"sphere\"\n";
    CHECK(error_line(sphere + "radius = 1e-30\n", "radius") == 3);
    CHECK(error_line(sphere + "radius = 1e5\n", "radius") == 3);
    CHECK(error_line(sphere + "position = [0, 2e6, 0]\n", "coordinate range") == 3);
    CHECK(error_line(kLight + "[scene]\nambient = 1e7\n", "ambient") == 4);
    CHECK(error_line(kLight + "[scene]\nbackground = [0, 2e6, 0]\n", "background") == 4);
}

TEST_CASE("directions of huge components are normalised without overflowing") {
    const Scene scene = parse_scene("[[light]]\ntype = \"directional\"\ndirection = [3e38, -3e38, 0]\n"
                                    "[camera]\nup = [0, 3e38, 1]\n",
                                    "s.toml");
    const glm::vec3 d = scene.lights[0].direction;
    CHECK(std::isfinite(d.x));
    CHECK(d.x == doctest::Approx(std::sqrt(0.5)));
    CHECK(d.y == doctest::Approx(-std::sqrt(0.5)));
    CHECK(glm::length(scene.camera.up) == doctest::Approx(1.0));
}

TEST_CASE("camera positions and clip distances outside the documented ranges are refused") {
    CHECK(error_line(kLight + "[camera]\nposition = [0, 0, 2e6]\n", "coordinate range") == 4);
    CHECK(error_line(kLight + "[camera]\ntarget = [-1e30, 0, 0]\n", "coordinate range") == 4);
    CHECK(error_line(kLight + "[camera]\nnear = 1e-7\n", "near") == 4);
    CHECK(error_line(kLight + "[camera]\nnear = 1e-6\nfar = 1e7\n") == -1);
    CHECK(error_line(kLight + "[camera]\nfar = 1e8\n", "far") == 4);
}

TEST_CASE("transforms: scales and translations outside the ranges are refused at their line") {
    // Before: scale = 1e-30 failed at reference time, after files were written; translate =
    // [1e30, 0, 0] tripped an assertion inside Embree.
    CHECK(error_line(kLight + kBox + "scale = 1e-30\n", "scale") == 5);
    CHECK(error_line(kLight + kBox + "scale = [1, 1e4, 1]\n", "scale") == 5);
    CHECK(error_line(kLight + kBox + "scale = [-0.001, 1000, 1]\n") == -1);  // mirrored, at the limits
    CHECK(error_line(kLight + kBox + "translate = [1e30, 0, 0]\n", "coordinate range") == 5);
    CHECK(error_line(kLight + kBox + "translate = [0, 0, -1000001]\n", "coordinate range") == 5);
    CHECK(error_line(kLight + kBox + "rotate = [0, 1e39, 0]\n", "single-precision") == 5);
    // Two legal scales that multiply to a flat object: refused at the instance.
    CHECK(error_line(kLight + kBox + "scale = 0.001\ninstances = [\n  { translate = [1, 0, 0] },\n"
                                     "  { scale = 0.001 },\n]\n",
                     "scale volumes") == 8);
}

TEST_CASE("every world-space vertex must lie in the coordinate range, whatever placed it there") {
    // Each transform is legal, but instance · object puts the box at 1.5e6.
    const Scene far = parse_scene(kLight + kBox + "translate = [1e6, 0, 0]\ninstances = [{ translate = [5e5, 0, 0] }]\n",
                                  "s.toml");
    const auto error = config_error_of([&] { build_scene_meshes(far); });
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(error->line() == 3);  // the [[object]]
    CHECK(contains(error->what(), "coordinate range"));

    // A large plane reaching past the bound.
    const Scene wide = parse_scene(kLight + "[[object]]\nshape = \"plane\"\nsize = [3e6, 1]\n", "s.toml");
    CHECK(config_error_of([&] { build_scene_meshes(wide); }));

    // Right up to the bound is fine.
    const Scene edge = parse_scene(kLight + kBox + "translate = [999999.5, 0, 0]\n", "s.toml");
    CHECK(!config_error_of([&] { build_scene_meshes(edge); }));
}

TEST_CASE("a scene with no objects loads (it renders its background)") {
    const Scene scene = parse_scene(kLight, "s.toml");
    CHECK(scene.objects.empty());
    CHECK(build_scene_meshes(scene).empty());
}

TEST_CASE("a mesh file key that names a directory says it is a directory") {
    const std::filesystem::path folder = std::filesystem::path(CANOPY_TEST_DATA) / "bad_input/meshes";
    const auto error = config_error_of([&] {
        parse_scene(kLight + "[[object]]\nshape = \"mesh\"\nfile = \"a_folder.obj\"\n", folder / "s.toml");
    });
    REQUIRE(error);
    INFO(error->formatted());
    CHECK(error->line() == 5);
    CHECK(contains(error->what(), "is a directory"));
    CHECK(!contains(error->what(), "not found"));
}
