// Image-error metrics: expected values are worked out by hand in the comments next to each check.
#include "metrics/colormaps.hpp"
#include "metrics/comparable_pair.hpp"
#include "metrics/error_maps.hpp"
#include "metrics/flip.hpp"
#include "metrics/image_metrics.hpp"
#include "metrics/pixel_error.hpp"
#include "metrics/shadow_error.hpp"
#include "metrics/ssim.hpp"

#include <doctest/doctest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

using namespace canopy;

namespace {

const double nan_value = std::numeric_limits<double>::quiet_NaN();

Image filled(int width, int height, float r, float g, float b, float a = 1.0f) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[0] = r;
            p[1] = g;
            p[2] = b;
            p[3] = a;
        }
    return image;
}

void set_rgb(Image& image, int x, int y, float r, float g, float b) {
    float* p = image.at(x, y);
    p[0] = r;
    p[1] = g;
    p[2] = b;
}

void set_gray(Image& image, int x, int y, float value) { set_rgb(image, x, y, value, value, value); }

// Every value a multiple of 1/64 in [0.25, 0.73], so offsets of 1/16 are exact in float.
Image textured(int width, int height) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            float* p = image.at(x, y);
            p[0] = float(16 + (x * 5 + y * 3) % 31) / 64.0f;
            p[1] = float(16 + (x * 7 + y * 11) % 31) / 64.0f;
            p[2] = float(16 + (x * 13 + y) % 31) / 64.0f;
            p[3] = 1.0f;
        }
    return image;
}

// Deterministic noise in [-1, 1] (own LCG: std distributions differ between standard libraries).
struct Lcg {
    std::uint32_t state;
    float next() {
        state = state * 1664525u + 1013904223u;
        return float(state >> 8) / float(1u << 23) * 2.0f - 1.0f;
    }
};

Image with_noise(const Image& base, float amplitude, std::uint32_t seed) {
    Image noisy = base;
    Lcg random{seed};
    for (size_t i = 0; i < noisy.pixels.size(); ++i)
        if (i % 4 != 3) noisy.pixels[i] += amplitude * random.next();
    return noisy;
}

// Visibility image: R = visible fraction, G = light-facing mask.
Image visibility_image(int width, int height) { return filled(width, height, 1.0f, 1.0f, 0.0f, 1.0f); }

void set_visibility(Image& visibility, int x, int y, float visible_fraction, float facing = 1.0f) {
    visibility.at(x, y)[0] = visible_fraction;
    visibility.at(x, y)[1] = facing;
}

double mean_flip(const Image& test, const Image& reference) {
    return pool_flip_map(compute_flip_map(test, reference)).mean;
}

// The image pair of tests/data/metrics/flip_reference.py pattern_images(): dyadic values, so the
// Python references see exactly these floats.
struct PatternPair {
    Image reference, test;
};

PatternPair pattern_images() {
    const int width = 24, height = 20;
    PatternPair images{filled(width, height, 0, 0, 0), filled(width, height, 0, 0, 0)};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float r = float((3 * x + y) % 16) / 16.0f;
            const float g = x >= 12 ? 0.75f : 0.125f;
            const float b = float((x * y) % 8) / 8.0f;
            set_rgb(images.reference, x, y, r, g, b);
            set_rgb(images.test, x, y, y < 10 ? float((3 * x + y + 1) % 16) / 16.0f : r,
                    x >= 13 ? 0.75f : 0.125f,  // edge shifted by one pixel
                    x < 6 ? b * 0.5f : b);
        }
    return images;
}

nlohmann::json read_reference(const std::string& name) {
    std::ifstream file(std::string(CANOPY_TEST_DATA) + "/metrics/" + name);
    REQUIRE(file.good());
    return nlohmann::json::parse(file);
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// MAE / RMSE / PSNR / max error
// ---------------------------------------------------------------------------------------------

TEST_CASE("constant offset d gives MAE = RMSE = d and PSNR = 20 log10(1/d); alpha is ignored") {
    const Image reference = textured(16, 12);
    Image test = reference;
    const float d = 1.0f / 16.0f;
    for (size_t i = 0; i < test.pixels.size(); ++i) {
        if (i % 4 == 3)
            test.pixels[i] = 0.0f;  // alpha 0 vs 1 everywhere: must not count
        else
            test.pixels[i] += d;
    }
    const PixelError error = compute_pixel_error(test, reference);
    CHECK(error.mae == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(error.rmse == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(error.psnr == doctest::Approx(24.0823996531).epsilon(1e-9));  // 20 log10(16)
    CHECK(error.max_error == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(error.included_pixels == 16 * 12);
}

TEST_CASE("PSNR uses peak 1.0 even when values exceed 1 (unlike OpenImageIO's PSNR)") {
    // Reference 4.0 everywhere, test 4.5: rmse 0.5, PSNR = 20 log10(1 / 0.5) = 6.0206 dB.
    // OpenImageIO would use peak 4.5 and report 19.08 dB.
    const Image reference = filled(8, 8, 4.0f, 4.0f, 4.0f);
    const Image test = filled(8, 8, 4.5f, 4.5f, 4.5f);
    CHECK(compute_pixel_error(test, reference).psnr == doctest::Approx(6.0205999133).epsilon(1e-9));
}

TEST_CASE("identical images: RMSE 0, PSNR inf (printed \"inf\"), SSIM 1, FLIP 0") {
    const Image image = textured(32, 24);
    const ImageMetrics metrics = compute_metrics(image, image, nullptr, nullptr, {});
    CHECK(metrics.mae == 0.0);
    CHECK(metrics.rmse == 0.0);
    CHECK(std::isinf(metrics.psnr));
    CHECK(metrics.psnr > 0.0);
    CHECK(format_metric_value(metrics.psnr) == "inf");
    CHECK(metrics.max_error == 0.0);
    CHECK(metrics.ssim == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(metrics.flip_mean == 0.0);
    CHECK(metrics.flip_median_weighted == 0.0);
    CHECK(metrics.nonfinite_pixels == 0);
    CHECK(std::isnan(metrics.light_bleeding));  // no visibility given
    CHECK(metrics.umbra_pixels == 0);
}

TEST_CASE("format_metric_value") {
    CHECK(format_metric_value(std::numeric_limits<double>::infinity()) == "inf");
    CHECK(format_metric_value(-std::numeric_limits<double>::infinity()) == "-inf");
    CHECK(format_metric_value(nan_value) == "nan");
    CHECK(format_metric_value(0.125) == "0.125");
    CHECK(format_metric_value(1.0 / 3.0) == "0.333333");
}

TEST_CASE("max error and its pixel for a single changed pixel") {
    const Image reference = filled(10, 6, 0.5f, 0.5f, 0.5f);
    Image test = reference;
    test.at(7, 4)[1] = 0.1f;   // |0.1 - 0.5| = 0.4 in G at (7, 4)
    test.at(2, 1)[0] = 0.75f;  // a smaller change elsewhere, 0.25
    const PixelError error = compute_pixel_error(test, reference);
    CHECK(error.max_error == doctest::Approx(0.4).epsilon(1e-6));
    CHECK(error.max_x == 7);
    CHECK(error.max_y == 4);
    // Sum of channel errors 0.4 + 0.25 over 10 * 6 * 3 = 180 values.
    CHECK(error.mae == doctest::Approx(0.65 / 180.0).epsilon(1e-6));
    // sqrt((0.16 + 0.0625) / 180)
    CHECK(error.rmse == doctest::Approx(std::sqrt(0.2225 / 180.0)).epsilon(1e-6));
}

// ---------------------------------------------------------------------------------------------
// SSIM
// ---------------------------------------------------------------------------------------------

TEST_CASE("SSIM of two uniform images has the closed form (2ab + C1) / (a^2 + b^2 + C1)") {
    // Zero variance everywhere, so the structure term is C2 / C2 = 1.
    // a = 0.5, b = 0.25: (0.25 + 0.0001) / (0.25 + 0.0625 + 0.0001) = 0.2501 / 0.3126.
    const Image a = filled(16, 16, 0.5f, 0.5f, 0.5f);
    const Image b = filled(16, 16, 0.25f, 0.25f, 0.25f);
    CHECK(compute_ssim(a, b) == doctest::Approx(0.2501 / 0.3126).epsilon(1e-6));
}

TEST_CASE("SSIM clamps luminance to [0, 1] before comparing") {
    // Luminance 2 and 1.5 both clamp to 1: no difference left.
    CHECK(compute_ssim(filled(12, 12, 2.0f, 2.0f, 2.0f), filled(12, 12, 1.5f, 1.5f, 1.5f)) ==
          doctest::Approx(1.0));
}

TEST_CASE("SSIM drops for a contrast-reduced copy and decreases with noise; it is symmetric") {
    const Image reference = textured(40, 32);
    Image low_contrast = reference;
    for (size_t i = 0; i < low_contrast.pixels.size(); ++i)
        if (i % 4 != 3) low_contrast.pixels[i] = 0.5f + 0.5f * (low_contrast.pixels[i] - 0.5f);
    const double contrast_ssim = compute_ssim(low_contrast, reference);
    CHECK(contrast_ssim < 0.99);
    CHECK(contrast_ssim > 0.5);

    const double slight = compute_ssim(with_noise(reference, 0.02f, 1), reference);
    const double medium = compute_ssim(with_noise(reference, 0.05f, 2), reference);
    const double strong = compute_ssim(with_noise(reference, 0.15f, 3), reference);
    CHECK(slight < 1.0);
    CHECK(medium < slight);
    CHECK(strong < medium);

    const Image noisy = with_noise(reference, 0.05f, 4);
    CHECK(compute_ssim(noisy, reference) == doctest::Approx(compute_ssim(reference, noisy)).epsilon(1e-12));
}

TEST_CASE("SSIM compares Rec. 709 luminance: two uniform colours by hand") {
    // Pure red has luminance 0.2126, pure blue 0.0722 (equal weights would make both 1/3 and
    // SSIM 1). Uniform images: SSIM = (2 a b + C1) / (a^2 + b^2 + C1).
    const double a = 0.2126, b = 0.0722, c1 = 1e-4;
    CHECK(compute_ssim(filled(16, 16, 1.0f, 0.0f, 0.0f), filled(16, 16, 0.0f, 0.0f, 1.0f)) ==
          doctest::Approx((2 * a * b + c1) / (a * a + b * b + c1)).epsilon(1e-5));
}

TEST_CASE("SSIM weighs a window's pixels with the 11x11 Gaussian of sigma 1.5: one changed pixel by hand") {
    // 21 x 21 grey 0.5 with the centre pixel at 0.75: every one of the 11 x 11 valid windows
    // holds that pixel, at offset (i, j) from its centre, with weight w = g_i g_j (g the
    // normalised Gaussian, sigma 1.5). In such a window the reference is constant, so
    //   mu_r = 0.5, mu_t = 0.5 + 0.25 w, var_r = cov = 0, var_t = w (1 - w) 0.25^2 and
    //   SSIM = (2 mu_t mu_r + C1) C2 / ((mu_t^2 + mu_r^2 + C1)(var_t + C2)); the result is their mean.
    const Image reference = filled(21, 21, 0.5f, 0.5f, 0.5f);
    Image test = reference;
    set_gray(test, 10, 10, 0.75f);
    double g[11], total = 0.0;
    for (int k = -5; k <= 5; ++k) total += g[k + 5] = std::exp(-k * k / (2.0 * 1.5 * 1.5));
    const double c1 = 1e-4, c2 = 9e-4;
    double sum = 0.0;
    for (int i = 0; i < 11; ++i)
        for (int j = 0; j < 11; ++j) {
            const double w = g[i] / total * g[j] / total;
            const double mu_t = 0.5 + 0.25 * w, mu_r = 0.5, var_t = w * (1.0 - w) * 0.0625;
            sum += (2 * mu_t * mu_r + c1) * c2 / ((mu_t * mu_t + mu_r * mu_r + c1) * (var_t + c2));
        }
    CHECK(compute_ssim(test, reference) == doctest::Approx(sum / 121.0).epsilon(1e-5));
}

TEST_CASE("SSIM matches an independent direct-window reference") {
    // tests/data/metrics/ssim_reference.py: 2D 11x11 Gaussian window, valid region, double precision.
    const PatternPair images = pattern_images();
    const double expected = read_reference("ssim_reference.json")["ssim"].get<double>();
    CHECK(compute_ssim(images.test, images.reference) == doctest::Approx(expected).epsilon(1e-6));
}

TEST_CASE("SSIM is NaN for images smaller than the 11x11 window") {
    CHECK(std::isnan(compute_ssim(filled(10, 20, 0.5f, 0.5f, 0.5f), filled(10, 20, 0.5f, 0.5f, 0.5f))));
    CHECK_FALSE(std::isnan(compute_ssim(filled(11, 11, 0.5f, 0.5f, 0.5f), filled(11, 11, 0.5f, 0.5f, 0.5f))));
}

// ---------------------------------------------------------------------------------------------
// FLIP
// ---------------------------------------------------------------------------------------------

TEST_CASE("FLIP of identical images is 0 at every pixel") {
    const Image image = textured(24, 24);
    const std::vector<float> map = compute_flip_map(image, image);
    REQUIRE(map.size() == 24 * 24);
    for (float value : map) CHECK(value == 0.0f);
}

TEST_CASE("FLIP black vs white is 0.96738, by hand from the paper's constants") {
    // Uniform images: the normalised CSF filters leave them unchanged and the feature term is 0,
    // so FLIP = compressed colour difference.
    //   HyAB(Lab black, Lab white) = |0 - 100| + 0 = 100;  100^0.7 = 25.11886
    //   c_max = HyAB(green, blue)^0.7 with Hunt-adjusted Lab green (87.736, -75.610, 72.981) and
    //           blue (32.298, 25.578, -34.836): (55.438 + 147.863)^0.7 = 203.3017^0.7 = 41.27610
    //   breakpoint p_c c_max = 16.51044;  25.11886 > breakpoint, so
    //   FLIP = 0.95 + (25.11886 - 16.51044) / (41.27610 - 16.51044) * 0.05 = 0.967380
    const std::vector<float> map = compute_flip_map(filled(16, 16, 1, 1, 1), filled(16, 16, 0, 0, 0));
    for (float value : map) CHECK(value == doctest::Approx(0.967380).epsilon(1e-5));
    // Values above 1 are clamped first (LDR-FLIP), so a brighter "white" changes nothing.
    CHECK(mean_flip(filled(16, 16, 5, 5, 5), filled(16, 16, 0, 0, 0)) == doctest::Approx(0.967380).epsilon(1e-5));
}

TEST_CASE("FLIP of a small grey-level change is small: 0.5 vs 0.51 gives 0.040698") {
    // L* = 116 Y^(1/3) - 16: 76.06926 for Y = 0.5, 76.67901 for Y = 0.51 (a*, b* = 0).
    // HyAB = 0.60975;  ^0.7 = 0.707303 < breakpoint 16.51044, so FLIP = 0.707303 * 0.95 / 16.51044.
    const double flip = mean_flip(filled(16, 16, 0.51f, 0.51f, 0.51f), filled(16, 16, 0.5f, 0.5f, 0.5f));
    CHECK(flip == doctest::Approx(0.040698).epsilon(1e-4));
    CHECK(flip < 0.05);
}

TEST_CASE("FLIP grows with the size and with the magnitude of a change") {
    const Image reference = filled(48, 48, 0.5f, 0.5f, 0.5f);
    auto with_square = [&](int size, float value) {
        Image test = reference;
        const int start = 24 - size / 2;
        for (int y = start; y < start + size; ++y)
            for (int x = start; x < start + size; ++x) set_gray(test, x, y, value);
        return test;
    };
    double previous = 0.0;
    for (int size : {1, 2, 4, 8, 16}) {
        const double flip = mean_flip(with_square(size, 0.8f), reference);
        CHECK(flip > previous);
        previous = flip;
    }
    previous = 0.0;
    for (float value : {0.52f, 0.55f, 0.6f, 0.7f, 0.9f}) {
        const double flip = mean_flip(with_square(8, value), reference);
        CHECK(flip > previous);
        previous = flip;
    }
}

TEST_CASE("FLIP matches an independent non-separable double-precision reference") {
    // tests/data/metrics/flip_reference.py computes LDR-FLIP with the paper's 2D kernels.
    const nlohmann::json expected = read_reference("flip_reference.json");
    const PatternPair images = pattern_images();
    const std::vector<float> map =
        compute_flip_map(images.test, images.reference, expected["pixels_per_degree"].get<double>());
    const std::vector<double> expected_map = expected["map"].get<std::vector<double>>();
    REQUIRE(map.size() == expected_map.size());
    double worst = 0.0;
    for (size_t i = 0; i < map.size(); ++i) worst = std::max(worst, std::abs(double(map[i]) - expected_map[i]));
    CHECK(worst < 1e-4);
    const FlipPooled pooled = pool_flip_map(map);
    CHECK(pooled.mean == doctest::Approx(expected["mean"].get<double>()).epsilon(1e-4));
    CHECK(pooled.weighted_median == doctest::Approx(expected["weighted_median"].get<double>()).epsilon(1e-4));
}

TEST_CASE("FLIP pooling: mean and the FLIP tool's weighted median, NaN entries skipped") {
    // Sorted 0.1, 0.2, 0.3, 0.4 (sum 1.0); running sums 0.1, 0.3, 0.6 > 0.5 -> weighted median 0.3
    // (the plain median would be 0.25).
    const FlipPooled pooled = pool_flip_map({0.4f, 0.1f, float(nan_value), 0.3f, 0.2f});
    CHECK(pooled.mean == doctest::Approx(0.25).epsilon(1e-6));
    CHECK(pooled.weighted_median == doctest::Approx(0.3).epsilon(1e-6));
    CHECK(pooled.pooled_pixels == 4);
    // Ties: 0.25, 0.25, 0.5 reaches exactly half (0.5) after the second value, which is not "more
    // than half", so the tool's rule moves on to 0.5.
    CHECK(pool_flip_map({0.5f, 0.25f, 0.25f}).weighted_median == doctest::Approx(0.5));
    CHECK(pool_flip_map({0.0f, 0.0f}).weighted_median == 0.0);
    CHECK(std::isnan(pool_flip_map({float(nan_value)}).mean));
}

TEST_CASE("FLIP rejects a non-positive pixels-per-degree") {
    const Image image = filled(4, 4, 0.5f, 0.5f, 0.5f);
    CHECK_THROWS_AS(compute_flip_map(image, image, 0.0), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Shadow metrics
// ---------------------------------------------------------------------------------------------

// 16x4 scene, all light-facing: columns 0-7 lit (V = 1, grey 0.8), columns 8-15 in umbra
// (V = 0, grey 0.1). Grey g has luminance g because the Rec. 709 weights sum to 1.
struct ShadowScene {
    Image reference = filled(16, 4, 0.8f, 0.8f, 0.8f);
    Image visibility = visibility_image(16, 4);
    ShadowScene() {
        for (int y = 0; y < 4; ++y)
            for (int x = 8; x < 16; ++x) {
                set_gray(reference, x, y, 0.1f);
                set_visibility(visibility, x, y, 0.0f);
            }
    }
};

TEST_CASE("a shadow edge shifted into the umbra gives the hand-computed light bleeding") {
    const ShadowScene scene;
    Image test = scene.reference;
    for (int y = 0; y < 4; ++y)
        for (int x = 8; x < 10; ++x) set_gray(test, x, y, 0.8f);  // edge moved 2 px right
    set_gray(test, 15, 3, 0.0f);  // darker than the reference in the umbra: not light bleeding
    set_gray(test, 0, 0, 1.0f);   // brighter in the lit region: not over-darkening
    // Umbra: 8 columns x 4 rows = 32 pixels; 8 of them (2 columns) are 0.7 too bright.
    // light_bleeding = 8 * 0.7 / 32 = 0.175; nothing in the lit region got darker.
    const ShadowError metrics = compute_shadow_error(test, scene.reference, scene.visibility, 1e-3);
    CHECK(metrics.umbra_pixels == 32);
    CHECK(metrics.lit_pixels == 32);
    CHECK(metrics.penumbra_pixels == 0);
    CHECK(metrics.light_bleeding == doctest::Approx(0.175).epsilon(1e-5));
    CHECK(metrics.over_darkening == doctest::Approx(0.0));
    CHECK(std::isnan(metrics.penumbra_rmse));
}

TEST_CASE("a shadow edge shifted into the lit region gives the hand-computed over-darkening") {
    const ShadowScene scene;
    Image test = scene.reference;
    for (int y = 0; y < 4; ++y)
        for (int x = 5; x < 8; ++x) set_gray(test, x, y, 0.1f);  // edge moved 3 px left
    // Lit: 32 pixels, 12 of them (3 columns) 0.7 too dark: 12 * 0.7 / 32 = 0.2625.
    const ShadowError error = compute_shadow_error(test, scene.reference, scene.visibility, 1e-3);
    CHECK(error.over_darkening == doctest::Approx(0.2625).epsilon(1e-5));
    CHECK(error.light_bleeding == doctest::Approx(0.0));
}

TEST_CASE("penumbra RMSE over 0 < V < 1, with the epsilon deciding umbra and lit") {
    Image reference = filled(4, 2, 0.45f, 0.45f, 0.45f);
    Image visibility = visibility_image(4, 2);
    Image test = reference;
    // Row 0: penumbra pixels with errors +0.1, -0.3, +0.1, -0.3.
    for (int x = 0; x < 4; ++x) {
        set_visibility(visibility, x, 0, 0.5f);
        set_gray(test, x, 0, x % 2 == 0 ? 0.55f : 0.15f);
    }
    // Row 1: V within epsilon of 0 and of 1 counts as umbra / lit, and 2e-3 from them as penumbra.
    set_visibility(visibility, 0, 1, 0.0005f);  // umbra
    set_visibility(visibility, 1, 1, 0.9995f);  // lit
    set_visibility(visibility, 2, 1, 0.002f);   // penumbra, error 0
    set_visibility(visibility, 3, 1, 0.998f);   // penumbra, error 0
    // RMSE = sqrt((2 * 0.01 + 2 * 0.09 + 0 + 0) / 6) = sqrt(0.2 / 6)
    const ShadowError error = compute_shadow_error(test, reference, visibility, 1e-3);
    CHECK(error.penumbra_pixels == 6);
    CHECK(error.umbra_pixels == 1);
    CHECK(error.lit_pixels == 1);
    CHECK(error.penumbra_rmse == doctest::Approx(std::sqrt(0.2 / 6.0)).epsilon(1e-5));
}

TEST_CASE("pixels with G = 0 (background, back-facing) are excluded from the shadow metrics") {
    const ShadowScene scene;
    Image visibility = scene.visibility;
    Image test = scene.reference;
    // Huge errors on rows 2-3, which are then masked out.
    for (int y = 2; y < 4; ++y)
        for (int x = 0; x < 16; ++x) {
            set_gray(test, x, y, x < 8 ? 0.0f : 1.0f);
            set_visibility(visibility, x, y, x < 8 ? 1.0f : 0.0f, 0.0f);
        }
    // Rows 0-1: one bleeding pixel (+0.4) in the umbra, one darkened pixel (-0.2) in the lit part.
    set_gray(test, 12, 0, 0.5f);
    set_gray(test, 3, 1, 0.6f);
    const ShadowError error = compute_shadow_error(test, scene.reference, visibility, 1e-3);
    CHECK(error.umbra_pixels == 16);
    CHECK(error.lit_pixels == 16);
    CHECK(error.light_bleeding == doctest::Approx(0.4 / 16.0).epsilon(1e-5));
    CHECK(error.over_darkening == doctest::Approx(0.2 / 16.0).epsilon(1e-5));
}

TEST_CASE("shadow metrics weigh R, G and B by Rec. 709 luminance: coloured errors by hand") {
    // Grey scenes hide the weights (they sum to 1); here each error sits in one channel.
    const ShadowScene scene;
    Image test = scene.reference;
    test.at(9, 0)[0] += 0.5f;   // umbra, red + 0.5:   luminance + 0.2126 * 0.5 = 0.1063
    test.at(10, 1)[2] += 0.5f;  // umbra, blue + 0.5:  + 0.0722 * 0.5 = 0.0361
    test.at(11, 2)[1] -= 0.05f; // umbra, darker: not light bleeding
    test.at(2, 0)[1] -= 0.3f;   // lit, green - 0.3:   - 0.7152 * 0.3 = 0.21456
    test.at(3, 1)[0] -= 0.4f;   // lit, red - 0.4:     - 0.2126 * 0.4 = 0.08504
    const ShadowError error = compute_shadow_error(test, scene.reference, scene.visibility, 1e-3);
    CHECK(error.light_bleeding == doctest::Approx((0.1063 + 0.0361) / 32.0).epsilon(1e-5));
    CHECK(error.over_darkening == doctest::Approx((0.21456 + 0.08504) / 32.0).epsilon(1e-5));

    // Penumbra: luminance errors 0.2126 * 0.2, 0.7152 * 0.1 and -0.0722 * 0.4.
    Image reference = filled(3, 1, 0.45f, 0.45f, 0.45f);
    Image visibility = visibility_image(3, 1);
    Image penumbra_test = reference;
    for (int x = 0; x < 3; ++x) set_visibility(visibility, x, 0, 0.5f);
    penumbra_test.at(0, 0)[0] += 0.2f;
    penumbra_test.at(1, 0)[1] += 0.1f;
    penumbra_test.at(2, 0)[2] -= 0.4f;
    const double r = 0.2126 * 0.2, g = 0.7152 * 0.1, b = 0.0722 * 0.4;
    CHECK(compute_shadow_error(penumbra_test, reference, visibility, 1e-3).penumbra_rmse ==
          doctest::Approx(std::sqrt((r * r + g * g + b * b) / 3.0)).epsilon(1e-5));
}

TEST_CASE("shadow metrics are NaN when the visibility has no pixels of that kind") {
    const Image reference = filled(4, 4, 0.5f, 0.5f, 0.5f);
    const Image all_lit = visibility_image(4, 4);
    const ShadowError error = compute_shadow_error(reference, reference, all_lit, 1e-3);
    CHECK(error.lit_pixels == 16);
    CHECK(error.over_darkening == 0.0);
    CHECK(std::isnan(error.light_bleeding));
    CHECK(std::isnan(error.penumbra_rmse));
    CHECK_THROWS_AS(compute_shadow_error(reference, reference, visibility_image(4, 3), 1e-3), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Non-finite pixels
// ---------------------------------------------------------------------------------------------

TEST_CASE("NaN/Inf test pixels are counted and every other metric uses the finite pixels only") {
    const Image reference = textured(24, 16);
    Image test = reference;
    for (size_t i = 0; i < test.pixels.size(); ++i)
        if (i % 4 != 3) test.pixels[i] += 1.0f / 16.0f;
    test.at(3, 4)[0] = std::numeric_limits<float>::quiet_NaN();
    test.at(20, 10)[1] = std::numeric_limits<float>::infinity();
    test.at(5, 5)[3] = std::numeric_limits<float>::quiet_NaN();  // alpha counts as a channel too

    const ImageMetrics metrics = compute_metrics(test, reference, nullptr, nullptr, {});
    CHECK(metrics.nonfinite_pixels == 3);
    // The 381 remaining pixels all have error exactly 1/16: not diluted, not NaN, not inf.
    CHECK(metrics.mae == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(metrics.rmse == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(metrics.max_error == doctest::Approx(0.0625).epsilon(1e-9));
    CHECK(std::isfinite(metrics.ssim));
    CHECK(metrics.ssim < 1.0);
    CHECK(std::isfinite(metrics.flip_mean));
    CHECK(std::isfinite(metrics.flip_median_weighted));

    const std::vector<float> map = compute_flip_map(test, reference);
    CHECK(std::isnan(map[4 * 24 + 3]));
    CHECK(std::isnan(map[10 * 24 + 20]));
    CHECK(std::isfinite(map[0]));
    CHECK(count_nonfinite_pixels(reference) == 0);
}

TEST_CASE("an all-NaN test image leaves nothing to measure") {
    const Image reference = filled(12, 12, 0.5f, 0.5f, 0.5f);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const ImageMetrics metrics = compute_metrics(filled(12, 12, nan, nan, nan), reference, nullptr, nullptr, {});
    CHECK(metrics.nonfinite_pixels == 144);
    CHECK(std::isnan(metrics.mae));
    CHECK(std::isnan(metrics.psnr));
    CHECK(std::isnan(metrics.ssim));
    CHECK(std::isnan(metrics.flip_mean));
}

TEST_CASE("mismatched sizes are rejected") {
    CHECK_THROWS_AS(compute_metrics(filled(4, 4, 0, 0, 0), filled(4, 5, 0, 0, 0), nullptr, nullptr, {}), std::invalid_argument);
    CHECK_THROWS_AS(compute_pixel_error(Image(), Image()), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// Error maps
// ---------------------------------------------------------------------------------------------

TEST_CASE("absolute error heatmap: viridis over [0, max_value], clamped, sRGB values, magenta for NaN") {
    const Image reference = filled(4, 1, 0.5f, 0.5f, 0.5f);
    Image test = reference;
    set_gray(test, 1, 0, 0.55f);  // |diff| 0.05 = half of max_value -> entry int(0.5 * 255 + 0.5) = 128
    set_gray(test, 2, 0, 0.0f);   // |diff| 0.5 > max_value -> clamped to the last entry
    test.at(3, 0)[2] = std::numeric_limits<float>::quiet_NaN();
    const Image heatmap = absolute_error_heatmap(test, reference, 0.1);
    const auto& viridis = viridis_colormap();
    CHECK(heatmap.at(0, 0)[0] == viridis[0][0]);
    CHECK(heatmap.at(0, 0)[2] == viridis[0][2]);
    CHECK(heatmap.at(1, 0)[1] == viridis[128][1]);
    CHECK(heatmap.at(2, 0)[0] == viridis[255][0]);
    CHECK(heatmap.at(2, 0)[3] == 1.0f);
    CHECK(heatmap.at(3, 0)[0] == 1.0f);
    CHECK(heatmap.at(3, 0)[1] == 0.0f);
    CHECK(heatmap.at(3, 0)[2] == 1.0f);
    CHECK_THROWS_AS(absolute_error_heatmap(test, reference, 0.0), std::invalid_argument);
}

TEST_CASE("FLIP heatmap uses FLIP's magma map and cyan for excluded pixels") {
    const Image heatmap = flip_heatmap({0.0f, 1.0f, 0.5f, float(nan_value)}, 2, 2);
    const auto& magma = magma_colormap();
    CHECK(heatmap.at(0, 0)[0] == magma[0][0]);
    CHECK(heatmap.at(1, 0)[0] == magma[255][0]);
    CHECK(heatmap.at(1, 0)[2] == magma[255][2]);
    // 0.5 * 255 + 0.5 = 128
    CHECK(heatmap.at(0, 1)[1] == magma[128][1]);
    CHECK(heatmap.at(1, 1)[0] == 0.0f);
    CHECK(heatmap.at(1, 1)[1] == 1.0f);
    CHECK(heatmap.at(1, 1)[2] == 1.0f);
    // Known matplotlib magma end points.
    CHECK(magma[0][2] == doctest::Approx(0.013866f));
    CHECK(magma[255][1] == doctest::Approx(0.991438f));
    CHECK_THROWS_AS(flip_heatmap({0.0f}, 2, 2), std::invalid_argument);
}
