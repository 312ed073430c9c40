// The population-coverage error (metrics/coverage_error.hpp) on small images with hand-computed
// answers: per pixel it counts aliasing, over 8x8 tiles and over the image it does not, and it
// sees grass thinned, thickened or moved.
#include "core/pixel_visibility.hpp"
#include "metrics/coverage_error.hpp"
#include "metrics/image_metrics.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

using namespace canopy;
namespace pv = canopy::pixel_visibility;

namespace {

// Coverage c(x, y) in channel B; the other channels hold junk the metric must not read.
Image coverage(int width, int height, const std::function<float(int, int)>& c) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[pv::kVisibility] = 0.3f;
            p[pv::kViewDepth] = 7.0f;
            p[pv::kCoverage] = c(x, y);
            p[pv::kSurface] = 1.0f;
        }
    return image;
}

}  // namespace

TEST_CASE("coverage error: identical coverage is no error") {
    const Image c = coverage(16, 16, [](int x, int y) { return float((x + y) % 5) / 4.0f; });
    const CoverageError e = compute_coverage_error(c, c);
    CHECK(e.mae == 0.0);
    CHECK(e.tile_mae == 0.0);
    CHECK(e.total_error == 0.0);
    CHECK(e.bias == 0.0);
    CHECK(e.pixels == 256 - 52);  // the 52 pixels with (x + y) % 5 == 0 are uncovered in both
}

TEST_CASE("coverage error: a one-sample raster's checkerboard over half-covered pixels is aliasing only") {
    // Every pixel half covered in truth; the raster's pixel centres hit the blade every other pixel.
    const Image truth = coverage(16, 16, [](int, int) { return 0.5f; });
    const Image raster = coverage(16, 16, [](int x, int y) { return float((x + y) % 2); });
    const CoverageError e = compute_coverage_error(raster, truth);
    CHECK(e.mae == doctest::Approx(0.5));
    CHECK(e.tile_mae == doctest::Approx(0.0));
    CHECK(e.total_error == doctest::Approx(0.0));
    CHECK(e.pixels == 256);
}

TEST_CASE("coverage error: thinned, thickened and moved grass") {
    const Image truth = coverage(16, 16, [](int x, int) { return x < 8 ? 0.6f : 0.0f; });
    SUBCASE("thinned to 3/4 everywhere") {
        const Image thin = coverage(16, 16, [](int x, int) { return x < 8 ? 0.45f : 0.0f; });
        const CoverageError e = compute_coverage_error(thin, truth);
        CHECK(e.mae == doctest::Approx(0.15));
        CHECK(e.tile_mae == doctest::Approx(0.15));
        CHECK(e.total_error == doctest::Approx(0.25));
        CHECK(e.bias == doctest::Approx(-0.25));
        CHECK(e.pixels == 128);
    }
    SUBCASE("thickened by a third") {
        const Image thick = coverage(16, 16, [](int x, int) { return x < 8 ? 0.8f : 0.0f; });
        const CoverageError e = compute_coverage_error(thick, truth);
        CHECK(e.bias == doctest::Approx(1.0 / 3.0));
        CHECK(e.total_error == doctest::Approx(1.0 / 3.0));
    }
    SUBCASE("moved by a whole tile: the total keeps, the tiles see it") {
        const Image moved = coverage(16, 16, [](int x, int) { return x >= 8 ? 0.6f : 0.0f; });
        const CoverageError e = compute_coverage_error(moved, truth);
        CHECK(e.total_error == doctest::Approx(0.0));
        CHECK(e.tile_mae == doctest::Approx(0.6));
        CHECK(e.mae == doctest::Approx(0.6));
        CHECK(e.pixels == 256);
    }
}

TEST_CASE("coverage error: edge tiles average over the pixels they have") {
    // 10 x 10: the right and bottom tiles are 2 pixels wide or tall. Only pixel (9, 9) differs.
    const Image truth = coverage(10, 10, [](int, int) { return 0.5f; });
    const Image raster = coverage(10, 10, [](int x, int y) { return x == 9 && y == 9 ? 0.9f : 0.5f; });
    const CoverageError e = compute_coverage_error(raster, truth);
    // Tiles: 8x8, 2x8, 8x2, 2x2; only the 2x2 one differs, by 0.4 / 4.
    CHECK(e.tile_mae == doctest::Approx(0.1 / 4.0));
    CHECK(e.mae == doctest::Approx(0.4 / 100.0));
}

TEST_CASE("coverage error: nothing covered, no truth, non-finite pixels and mismatched sizes") {
    const Image empty = coverage(8, 8, [](int, int) { return 0.0f; });
    const CoverageError none = compute_coverage_error(empty, empty);
    CHECK(none.pixels == 0);
    CHECK(std::isnan(none.mae));
    CHECK(std::isnan(none.tile_mae));
    CHECK(std::isnan(none.total_error));

    // Grass where the truth has none: per-pixel and tile errors, no relative total.
    const Image some = coverage(8, 8, [](int x, int) { return x == 0 ? 1.0f : 0.0f; });
    const CoverageError invented = compute_coverage_error(some, empty);
    CHECK(invented.mae == doctest::Approx(1.0));
    CHECK(invented.tile_mae == doctest::Approx(8.0 / 64.0));
    CHECK(std::isnan(invented.total_error));
    CHECK(std::isnan(invented.bias));

    const float nan = std::numeric_limits<float>::quiet_NaN();
    const Image truth = coverage(8, 8, [](int, int) { return 0.5f; });
    const Image broken = coverage(8, 8, [&](int x, int y) { return x == 3 && y == 3 ? nan : 0.5f; });
    const CoverageError skipped = compute_coverage_error(broken, truth);
    CHECK(skipped.pixels == 63);
    CHECK(skipped.mae == 0.0);
    CHECK(skipped.total_error == 0.0);

    CHECK_THROWS_AS(compute_coverage_error(coverage(8, 8, [](int, int) { return 0.0f; }),
                                           coverage(8, 9, [](int, int) { return 0.0f; })),
                    std::invalid_argument);
}

TEST_CASE("compute_metrics: coverage columns only where the technique declares them") {
    Image image(8, 8), truth(8, 8);
    const Image technique = coverage(8, 8, [](int, int) { return 0.4f; });
    const Image reference = coverage(8, 8, [](int, int) { return 0.5f; });
    const CoveragePair pair{technique, reference};

    const ImageMetrics none = compute_metrics(image, truth, nullptr, &pair, ErrorColumns{});
    CHECK(std::isnan(none.coverage_mae));
    CHECK(none.coverage_pixels == 0);

    const ImageMetrics declared = compute_metrics(image, truth, nullptr, &pair, ErrorColumns{.coverage = true});
    CHECK(declared.coverage_mae == doctest::Approx(0.1));
    CHECK(declared.coverage_tile_mae == doctest::Approx(0.1));
    CHECK(declared.coverage_total_error == doctest::Approx(0.2));
    CHECK(declared.coverage_pixels == 64);

    const ImageMetrics without = compute_metrics(image, truth, nullptr, nullptr, ErrorColumns{.coverage = true});
    CHECK(std::isnan(without.coverage_mae));

    CHECK_FALSE(ErrorColumns{.visibility = true, .coverage = true}.consistent());
    CHECK(ErrorColumns{.coverage = true}.consistent());
}
