// Every grass technique (and its tested variants) at the extremes the grass issue lists:
// density 0 and 1, the sun at the horizon and at the zenith, the camera down among the blades,
// blades smaller than a pixel, a field of one cell, and a camera straight above a cell (where a
// camera-facing billboard has no horizontal direction to turn to). Every image is finite and
// non-negative; density 0 shows no grass and density 1 some (a flat slice seen obliquely covers
// the least: 55 of 3,072 pixels).
#include "support/bake_truth.hpp"

#include "config/scene_config.hpp"
#include "support/technique_variants.hpp"
#include "support/test_gpu.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace canopy;

namespace {

struct Extreme {
    const char* name;
    std::string camera, light, params;
};

Scene extreme_scene(const Extreme& e) {
    return parse_scene(std::string("[scene]\nname = \"extreme\"\nambient = 0.1\n") + e.camera + "\n[[light]]\ntype = \"directional\"\n" +
                           e.light + "\ncasts_shadows = false\n[[object]]\nname = \"ground\"\nshape = \"plane\"\nsize = [6, 6]\n"
                           "albedo = [0.6, 0.3, 0.1]\n[[population]]\nname = \"grass\"\nkind = \"grass\"\n"
                           "albedo = [0.1, 0.8, 0.1]\nparams = { blades = 80, " + e.params + " }\n",
                       "extreme.toml");
}

const char* kCamera = "[camera]\nposition = [0, 1.5, 3]\ntarget = [0, 0, 0]";
const char* kSun = "direction = [-0.3, -1, -0.2]";

}  // namespace

TEST_CASE("grass techniques at the extremes: finite, non-negative images; density 0 draws no blade") {
    const std::vector<Extreme> extremes = {
        // Wide blades, so that density 1 covers pixel centres at 64 x 48.
        {"density 0", kCamera, kSun, "cells_x = 2, cells_z = 2, density = 0.0, width_min = 0.04, width_max = 0.06"},
        {"density 1", kCamera, kSun, "cells_x = 2, cells_z = 2, density = 1.0, width_min = 0.04, width_max = 0.06"},
        {"sun at the horizon", kCamera, "direction = [1, 0, 0]", "cells_x = 2, cells_z = 2"},
        {"sun at the zenith", kCamera, "direction = [0, -1, 0]", "cells_x = 2, cells_z = 2"},
        {"camera among the blades", "[camera]\nposition = [0.1, 0.04, 0.2]\ntarget = [1, 0.05, 0.4]\nnear = 0.001",
         kSun, "cells_x = 3, cells_z = 3"},
        {"blades smaller than a pixel", "[camera]\nposition = [0, 4, 6]\ntarget = [0, 0, 0]", kSun,
         "cells_x = 16, cells_z = 16, cell_size = 0.05"},
        {"a field of one cell", kCamera, kSun, "cells_x = 1, cells_z = 1"},
        {"camera straight above a cell", "[camera]\nposition = [0.5, 3, 0.5]\ntarget = [0.5, 0, 0.5]\nup = [0, 0, 1]",
         kSun, "cells_x = 1, cells_z = 1, centre_x = 0.5, centre_z = 0.5"},
    };
    for (const Extreme& e : extremes) {
        const std::string extreme = e.name;
        CAPTURE(extreme);
        const Scene scene = extreme_scene(e);
        for (const test::TechniqueVariant& variant : test::technique_variants("grass")) {
            const std::string name = test::describe(variant);
            CAPTURE(name);
            const Image image = test::render_technique(scene, variant.technique, variant.params, 64, 48);
            long long nonfinite = 0, negative = 0;
            float lowest = 0.0f;
            for (float v : image.pixels) {
                nonfinite += !std::isfinite(v);
                negative += v < 0.0f;
                lowest = std::min(lowest, v);
            }
            CAPTURE(lowest);
            CHECK(nonfinite == 0);
            CHECK(negative == 0);
            if (std::string(e.name) == "density 0") CHECK(grass::test::grass_pixels(image) == 0);
            if (std::string(e.name) == "density 1") CHECK(grass::test::grass_pixels(image) > 20);
        }
    }
}
