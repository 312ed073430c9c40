#include "metrics/ssim.hpp"

#include "metrics/comparable_pair.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace canopy {

namespace {

constexpr int window_radius = 5;  // 11x11 window
constexpr int window_size = 2 * window_radius + 1;
constexpr double window_sigma = 1.5;
constexpr double c1 = 0.01 * 0.01;  // (K1 L)^2 with L = 1
constexpr double c2 = 0.03 * 0.03;  // (K2 L)^2

std::array<double, window_size> gaussian_window() {
    std::array<double, window_size> weights{};
    double sum = 0.0;
    for (int i = 0; i < window_size; ++i) {
        const double d = i - window_radius;
        weights[i] = std::exp(-d * d / (2.0 * window_sigma * window_sigma));
        sum += weights[i];
    }
    for (double& w : weights) w /= sum;
    return weights;
}

std::vector<double> clamped_luminance(const Image& image) {
    std::vector<double> luminance(size_t(image.width) * size_t(image.height));
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            luminance[size_t(y) * size_t(image.width) + size_t(x)] =
                std::clamp(double(image.luminance(x, y)), 0.0, 1.0);
    return luminance;
}

}  // namespace

double compute_ssim(const Image& test, const Image& reference) {
    const ComparablePair pair = make_comparable_pair(test, reference);
    const int width = test.width;
    const int height = test.height;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (width < window_size || height < window_size) return nan;

    const std::vector<double> a = clamped_luminance(pair.test);
    const std::vector<double> b = clamped_luminance(pair.reference);
    const auto weights = gaussian_window();

    // Horizontal pass ("valid" columns only) of the five local moments.
    const int out_width = width - 2 * window_radius;
    const int out_height = height - 2 * window_radius;
    enum Moment { mean_a, mean_b, mean_aa, mean_bb, mean_ab, moment_count };
    std::vector<std::array<double, moment_count>> horizontal(size_t(out_width) * size_t(height));
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < out_width; ++x) {
            std::array<double, moment_count> sums{};
            for (int k = 0; k < window_size; ++k) {
                const size_t i = size_t(y) * size_t(width) + size_t(x + k);
                const double w = weights[k];
                sums[mean_a] += w * a[i];
                sums[mean_b] += w * b[i];
                sums[mean_aa] += w * a[i] * a[i];
                sums[mean_bb] += w * b[i] * b[i];
                sums[mean_ab] += w * a[i] * b[i];
            }
            horizontal[size_t(y) * size_t(out_width) + size_t(x)] = sums;
        }
    }

    // Vertical pass, SSIM per window, and pooling.
    double ssim_sum = 0.0;
    long long window_count = 0;
    for (int y = 0; y < out_height; ++y) {
        for (int x = 0; x < out_width; ++x) {
            const int centre_x = x + window_radius;
            const int centre_y = y + window_radius;
            if (!pair.included[size_t(centre_y) * size_t(width) + size_t(centre_x)]) continue;
            std::array<double, moment_count> m{};
            for (int k = 0; k < window_size; ++k) {
                const auto& h = horizontal[size_t(y + k) * size_t(out_width) + size_t(x)];
                for (int j = 0; j < moment_count; ++j) m[j] += weights[k] * h[j];
            }
            const double variance_a = m[mean_aa] - m[mean_a] * m[mean_a];
            const double variance_b = m[mean_bb] - m[mean_b] * m[mean_b];
            const double covariance = m[mean_ab] - m[mean_a] * m[mean_b];
            const double numerator = (2.0 * m[mean_a] * m[mean_b] + c1) * (2.0 * covariance + c2);
            const double denominator =
                (m[mean_a] * m[mean_a] + m[mean_b] * m[mean_b] + c1) * (variance_a + variance_b + c2);
            ssim_sum += numerator / denominator;
            ++window_count;
        }
    }
    return window_count > 0 ? ssim_sum / double(window_count) : nan;
}

}  // namespace canopy
