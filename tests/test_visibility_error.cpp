// The technique-isolated error and the pixel classes behind it (metrics/pixel_classes.hpp,
// metrics/visibility_error.hpp), on small pixel-visibility images with hand-computed answers.
#include "core/pixel_visibility.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/pixel_classes.hpp"
#include "metrics/visibility_error.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace canopy;
namespace pv = canopy::pixel_visibility;

namespace {

// Every pixel sees a surface at view depth 10, visibility `v`.
Image surfaces(int width, int height, float v = 1.0f) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[pv::kVisibility] = v;
            p[pv::kViewDepth] = 10.0f;
            p[pv::kSurface] = 1.0f;
        }
    return image;
}

void set_v(Image& image, int x, int y, float v) { image.at(x, y)[pv::kVisibility] = v; }

void set_background(Image& image, int x, int y) {
    float* p = image.at(x, y);
    p[pv::kVisibility] = pv::kNotLit;
    p[pv::kViewDepth] = 0.0f;
    p[pv::kSurface] = 0.0f;
}

// A shadow edge: columns x < `edge` in umbra (V = 0), the rest lit.
Image edge(int width, int height, int edge) {
    Image image = surfaces(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < edge; ++x) set_v(image, x, y, 0.0f);
    return image;
}

Image grey(int width, int height, float value) {
    Image image(width, height);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = (i % 4 == 3) ? 1.0f : value;
    return image;
}

VisibilityError error_of(const Image& technique, const Image& reference) {
    return compute_visibility_error(technique, reference, classify_pixels(technique, reference), 1e-3);
}

}  // namespace

TEST_CASE("visibility MAE, RMSE and penumbra RMSE, by hand") {
    Image reference = surfaces(4, 2), technique = surfaces(4, 2);
    // Reference row 0: 0, 0.5, 1, 1; row 1: 0.25, 0.75, 0, 1 (penumbra: 0.5, 0.25, 0.75).
    const float truth[8] = {0.0f, 0.5f, 1.0f, 1.0f, 0.25f, 0.75f, 0.0f, 1.0f};
    // Differences: +0.2 (umbra), -0.5 (penumbra), 0, -0.1, +0.25 (penumbra), 0 (penumbra), +1 (umbra), 0.
    const float given[8] = {0.2f, 0.0f, 1.0f, 0.9f, 0.5f, 0.75f, 1.0f, 1.0f};
    for (int i = 0; i < 8; ++i) {
        set_v(reference, i % 4, i / 4, truth[i]);
        set_v(technique, i % 4, i / 4, given[i]);
    }
    const VisibilityError e = error_of(technique, reference);
    CHECK(e.pixels == 8);
    CHECK(e.penumbra_pixels == 3);
    CHECK(e.excluded_fraction == 0.0);
    CHECK(e.mae == doctest::Approx((0.2 + 0.5 + 0.1 + 0.25 + 1.0) / 8.0).epsilon(1e-6));
    CHECK(e.rmse == doctest::Approx(std::sqrt((0.04 + 0.25 + 0.01 + 0.0625 + 1.0) / 8.0)).epsilon(1e-6));
    CHECK(e.penumbra_rmse == doctest::Approx(std::sqrt((0.25 + 0.0625 + 0.0) / 3.0)).epsilon(1e-6));
}

TEST_CASE("a shifted visibility buffer raises the error from 0: a metric that always read 0 would fail") {
    const Image reference = edge(16, 4, 8);
    CHECK(error_of(reference, reference).rmse == 0.0);
    // The technique's shadow edge two pixels to the right: 2 columns x 4 rows wrong by 1 of 64.
    const Image shifted = edge(16, 4, 10);
    const VisibilityError e = error_of(shifted, reference);
    CHECK(e.pixels == 64);
    CHECK(e.mae == doctest::Approx(8.0 / 64.0));
    CHECK(e.rmse == doctest::Approx(std::sqrt(8.0 / 64.0)));
    // A widened footprint: the edge spread into a ramp over four columns (V = 0.2 ... 0.8).
    Image widened = reference;
    for (int y = 0; y < 4; ++y)
        for (int k = 0; k < 4; ++k) set_v(widened, 6 + k, y, 0.2f * float(k + 1));
    // Columns 6, 7 (truth 0) read 0.2, 0.4; columns 8, 9 (truth 1) read 0.6, 0.8.
    CHECK(error_of(widened, reference).mae == doctest::Approx(4.0 * (0.2 + 0.4 + 0.4 + 0.2) / 64.0).epsilon(1e-6));
}

TEST_CASE("compared pixels: the light reaches the reference's surface, the raster drew and lit the same one") {
    Image reference = surfaces(6, 1, 0.5f), technique = surfaces(6, 1, 0.5f);
    set_background(reference, 0, 0);                        // background in both: not reached
    set_background(technique, 0, 0);
    set_v(reference, 1, 0, pv::kNotLit);                    // the light does not reach it: not reached
    set_background(technique, 2, 0);                        // the raster drew nothing there: excluded
    technique.at(3, 0)[pv::kViewDepth] = 10.5f;             // the raster drew another surface: excluded
    set_v(technique, 4, 0, pv::kNotLit);                    // the raster did not light it: excluded
    technique.at(5, 0)[pv::kViewDepth] = 10.0f * (1.0f + 5e-4f);  // the same surface, within 1e-3: compared
    set_v(technique, 5, 0, 0.75f);
    const PixelClasses classes = classify_pixels(technique, reference);
    CHECK(classes.reached == 4);
    CHECK(classes.compared_count == 1);
    CHECK(classes.excluded_fraction == doctest::Approx(0.75));
    const VisibilityError e = compute_visibility_error(technique, reference, classes, 1e-3);
    CHECK(e.pixels == 1);
    CHECK(e.mae == doctest::Approx(0.25));
    CHECK(e.excluded_fraction == doctest::Approx(0.75));

    // A NaN on either side leaves the pixel out; nothing compared reads NaN, not 0.
    Image nan = surfaces(2, 1, std::numeric_limits<float>::quiet_NaN());
    const VisibilityError none = error_of(nan, surfaces(2, 1));
    CHECK(none.pixels == 0);
    CHECK(std::isnan(none.rmse));
    CHECK(none.excluded_fraction == 1.0);
    CHECK_THROWS_AS(classify_pixels(surfaces(2, 1), surfaces(2, 2)), std::invalid_argument);
}

TEST_CASE("the shadow regions leave out silhouettes, not planes seen at a grazing angle") {
    const int width = 14, height = 9;
    Image reference = surfaces(width, height);
    // A plane receding steeply along x: 1 / depth linear in x (perspective), depth 2 ... 50.
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) reference.at(x, y)[pv::kViewDepth] = 1.0f / (0.5f - 0.036f * float(x));
    Image technique = reference;
    PixelClasses plane = classify_pixels(technique, reference);
    CHECK(plane.compared_count == width * height);
    CHECK(plane.region_count == width * height);  // no silhouette on a plane, however steep

    // A nearer object over columns 5-9 of rows 2-6 (depth 1): its rim and the plane's pixels next
    // to it are silhouettes, its inside is not; so are the plane's pixels next to a background
    // pixel at (0, 0).
    for (int y = 2; y <= 6; ++y)
        for (int x = 5; x <= 9; ++x) reference.at(x, y)[pv::kViewDepth] = 1.0f;
    set_background(reference, 0, 0);
    technique = reference;
    const PixelClasses classes = classify_pixels(technique, reference);
    const auto in_region = [&](int x, int y) { return classes.region[size_t(y) * width + size_t(x)] != 0; };
    CHECK(classes.compared_count == width * height - 1);
    for (int y = 1; y <= 7; ++y)
        for (int x = 4; x <= 10; ++x) {
            CAPTURE(x);
            CAPTURE(y);
            const bool inside = x >= 6 && x <= 8 && y >= 3 && y <= 5;
            const bool corner = (x == 4 || x == 10) && (y == 1 || y == 7);  // touches the object diagonally only
            CHECK(in_region(x, y) == (inside || corner));
        }
    CHECK(in_region(2, 4));
    CHECK(in_region(12, 4));
    CHECK_FALSE(in_region(1, 0));  // next to the background
    CHECK_FALSE(in_region(0, 1));
    CHECK(in_region(1, 1));
    // The region feeds compute_shadow_error as G; R is the reference's V there.
    const Image region = shadow_region_visibility(reference, classes);
    CHECK(region.at(2, 4)[1] == 1.0f);
    CHECK(region.at(5, 4)[1] == 0.0f);
}

TEST_CASE("compute_metrics: visibility and shadow-region columns only where the technique declares them") {
    // A 16 x 4 shadow edge at column 8, a technique whose edge is 2 columns to the right.
    const Image reference_v = edge(16, 4, 8), technique_v = edge(16, 4, 10);
    Image truth = grey(16, 4, 0.8f), image = grey(16, 4, 0.8f);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 10; ++x) {
            if (x < 8) truth.at(x, y)[0] = truth.at(x, y)[1] = truth.at(x, y)[2] = 0.1f;
            image.at(x, y)[0] = image.at(x, y)[1] = image.at(x, y)[2] = 0.1f;
        }
    const PixelVisibilityPair pair{technique_v, reference_v};

    const ImageMetrics none = compute_metrics(image, truth, &pair, nullptr, ErrorColumns{});
    CHECK(none.rmse > 0.0);
    CHECK(std::isnan(none.visibility_rmse));
    CHECK(std::isnan(none.light_bleeding));
    CHECK(none.columns == ErrorColumns{});

    const ErrorColumns shadow{.visibility = true, .shadow_regions = true};
    const ImageMetrics all = compute_metrics(image, truth, &pair, nullptr, shadow);
    CHECK(all.columns == shadow);
    CHECK(all.visibility_rmse == doctest::Approx(std::sqrt(8.0 / 64.0)));
    CHECK(all.visibility_pixels == 64);
    CHECK(all.visibility_excluded == 0.0);
    // The technique is too dark in columns 8-9 of the reference's lit part: 0.7 missing there.
    CHECK(all.umbra_pixels == 32);
    CHECK(all.lit_pixels == 32);
    CHECK(all.light_bleeding == doctest::Approx(0.0));
    CHECK(all.over_darkening == doctest::Approx(8 * 0.7 / 32.0).epsilon(1e-5));

    const ImageMetrics without = compute_metrics(image, truth, nullptr, nullptr, shadow);
    CHECK(std::isnan(without.visibility_rmse));
    CHECK(without.rmse == all.rmse);
}
