// Lookups of prefiltered moment maps on the device: where a LINEAR sampler would blend the wrong
// quantity, the lit pass fetches the four texels (bilinear_texels.glsl) and blends them itself.
// Checked through whole renders, so the shaders the techniques run are what is tested.
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>

using namespace canopy;

namespace {

constexpr int kWidth = 192, kHeight = 128;

struct Difference {
    float largest = 0.0f;
    long long pixels_over = 0;  // luminance differs by more than the threshold
};

Difference compare(const Image& a, const Image& b, float threshold) {
    Difference d;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            const float delta = std::abs(a.luminance(x, y) - b.luminance(x, y));
            d.largest = std::max(d.largest, delta);
            d.pixels_over += delta > threshold;
        }
    return d;
}

}  // namespace

// With linear storage the LINEAR lookup blends exp(c z), the right filter, and the box prefilter
// averages exp(c z) too; log storage (c z, log-sum-exp prefilter) must give the same image. A
// lookup that blends the logs instead darkens every texel-to-texel transition of the penumbra
// (a geometric mean): at c = 40 by up to ~0.2 in luminance here.
TEST_CASE("ESM: log-space storage renders what linear storage renders") {
    const Scene scene = test::tiny_scene_under_rect_light();
    for (long long resolution : {128LL, 512LL}) {
        for (double c : {10.0, 40.0}) {
            const std::map<std::string, ParamValue> base{{"resolution", resolution}, {"exponent", c}, {"filter", 5LL}};
            std::map<std::string, ParamValue> log_space = base;
            log_space["log_space"] = true;
            const Image linear = test::render_technique(scene, "shadow.esm", base, kWidth, kHeight);
            const Image logs = test::render_technique(scene, "shadow.esm", log_space, kWidth, kHeight);
            const Difference d = compare(linear, logs, 1e-3f);
            CAPTURE(resolution);
            CAPTURE(c);
            MESSAGE("ESM resolution ", resolution, ", c = ", c, ": largest luminance difference log vs linear ", d.largest,
                    ", pixels over 1e-3: ", d.pixels_over);
            CHECK(d.largest < 2e-3f);
            CHECK(d.pixels_over == 0);
        }
    }
}
