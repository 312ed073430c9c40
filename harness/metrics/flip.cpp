#include "metrics/flip.hpp"

#include "metrics/comparable_pair.hpp"
#include "reference/parallel_for.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

namespace canopy {

namespace {

// Single precision throughout, like the reference implementation, so that results agree with the
// FLIP tool to float rounding.
constexpr float pi = std::numbers::pi_v<float>;

// Paper constants.
constexpr float q_c = 0.7f;   // colour difference exponent
constexpr float p_c = 0.4f;   // colour difference breakpoint (fraction of the maximum)
constexpr float p_t = 0.95f;  // value the breakpoint maps to
constexpr float feature_width = 0.082f;  // w, degrees
constexpr float q_f = 0.5f;   // feature difference exponent

// CSF Gaussians (a, b) per opponent channel; blue-yellow is a sum of two.
constexpr float achromatic_a = 1.0f, achromatic_b = 0.0047f;
constexpr float red_green_a = 1.0f, red_green_b = 0.0053f;
constexpr float blue_yellow_a1 = 34.1f, blue_yellow_b1 = 0.04f;
constexpr float blue_yellow_a2 = 13.5f, blue_yellow_b2 = 0.025f;
constexpr float largest_b = 0.04f;

// D65 white point, and its reciprocal, as in FLIP.
constexpr float white[3] = {0.950428545f, 1.000000000f, 1.088900371f};
constexpr float inverse_white[3] = {1.052156925f, 1.000000000f, 0.918357670f};

struct Color {
    float x, y, z;
};

Color linear_rgb_to_xyz(Color rgb) {
    const float a11 = 10135552.0f / 24577794.0f, a12 = 8788810.0f / 24577794.0f, a13 = 4435075.0f / 24577794.0f;
    const float a21 = 2613072.0f / 12288897.0f, a22 = 8788810.0f / 12288897.0f, a23 = 887015.0f / 12288897.0f;
    const float a31 = 1425312.0f / 73733382.0f, a32 = 8788810.0f / 73733382.0f, a33 = 70074185.0f / 73733382.0f;
    return {a11 * rgb.x + a12 * rgb.y + a13 * rgb.z, a21 * rgb.x + a22 * rgb.y + a23 * rgb.z,
            a31 * rgb.x + a32 * rgb.y + a33 * rgb.z};
}

Color xyz_to_linear_rgb(Color xyz) {
    return {3.241003275f * xyz.x - 1.537398934f * xyz.y - 0.498615861f * xyz.z,
            -0.969224334f * xyz.x + 1.875930071f * xyz.y + 0.041554224f * xyz.z,
            0.055639423f * xyz.x - 0.204011202f * xyz.y + 1.057148933f * xyz.z};
}

Color xyz_to_ycxcz(Color xyz) {
    const float x = xyz.x * inverse_white[0], y = xyz.y * inverse_white[1], z = xyz.z * inverse_white[2];
    return {116.0f * y - 16.0f, 500.0f * (x - y), 200.0f * (y - z)};
}

Color ycxcz_to_xyz(Color ycxcz) {
    const float y = (ycxcz.x + 16.0f) / 116.0f;
    return {(y + ycxcz.y / 500.0f) * white[0], y * white[1], (y - ycxcz.z / 200.0f) * white[2]};
}

Color xyz_to_lab(Color xyz) {
    const float delta = 6.0f / 29.0f;
    const float delta_cube = delta * delta * delta;
    const float factor = 1.0f / (3.0f * delta * delta);
    const float term = 4.0f / 29.0f;
    auto f = [&](float t) { return t > delta_cube ? std::pow(t, 1.0f / 3.0f) : factor * t + term; };
    const float fx = f(xyz.x * inverse_white[0]), fy = f(xyz.y * inverse_white[1]), fz = f(xyz.z * inverse_white[2]);
    return {116.0f * fy - 16.0f, 500.0f * (fx - fy), 200.0f * (fy - fz)};
}

Color clamp01(Color c) {
    return {std::clamp(c.x, 0.0f, 1.0f), std::clamp(c.y, 0.0f, 1.0f), std::clamp(c.z, 0.0f, 1.0f)};
}

// Hunt effect: chroma shrinks with lightness.
Color hunt_adjusted_lab(Color lab) { return {lab.x, 0.01f * lab.x * lab.y, 0.01f * lab.x * lab.z}; }

// City-block in lightness plus Euclidean in the chromatic plane.
float hyab(Color a, Color b) {
    const float da = a.y - b.y, db = a.z - b.z;
    return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

// The largest colour difference FLIP can report: pure green versus pure blue.
float max_colour_difference() {
    const Color green = hunt_adjusted_lab(xyz_to_lab(linear_rgb_to_xyz({0.0f, 1.0f, 0.0f})));
    const Color blue = hunt_adjusted_lab(xyz_to_lab(linear_rgb_to_xyz({0.0f, 0.0f, 1.0f})));
    return std::pow(hyab(green, blue), q_c);
}

// Amplitude-form 1D Gaussian of the paper, a sqrt(pi / b) exp(-pi^2 x^2 / b).
float csf_gaussian(float x_squared, float a, float b) {
    return a * std::sqrt(pi / b) * std::exp(-pi * pi * x_squared / b);
}

// Square root of the amplitude, so that the 2D sum of two Gaussians separates into two 1D passes
// (NVlabs/flip misc/separatedConvolutions.pdf).
float csf_gaussian_sqrt_amplitude(float x_squared, float a, float b) {
    return std::sqrt(a * std::sqrt(pi / b)) * std::exp(-pi * pi * x_squared / b);
}

struct SpatialFilters {
    int radius = 0;
    std::vector<float> achromatic, red_green, blue_yellow_1, blue_yellow_2;
};

SpatialFilters make_spatial_filters(float ppd) {
    SpatialFilters filters;
    filters.radius = int(std::ceil(3.0f * std::sqrt(largest_b / (2.0f * pi * pi)) * ppd));
    const int width = 2 * filters.radius + 1;
    const float degrees_per_pixel = 1.0f / ppd;
    float sum_achromatic = 0.0f, sum_red_green = 0.0f, sum_blue_yellow_1 = 0.0f, sum_blue_yellow_2 = 0.0f;
    for (int i = 0; i < width; ++i) {
        const float x = float(i - filters.radius) * degrees_per_pixel;
        const float x2 = x * x;
        filters.achromatic.push_back(csf_gaussian(x2, achromatic_a, achromatic_b));
        filters.red_green.push_back(csf_gaussian(x2, red_green_a, red_green_b));
        filters.blue_yellow_1.push_back(csf_gaussian_sqrt_amplitude(x2, blue_yellow_a1, blue_yellow_b1));
        filters.blue_yellow_2.push_back(csf_gaussian_sqrt_amplitude(x2, blue_yellow_a2, blue_yellow_b2));
        sum_achromatic += filters.achromatic.back();
        sum_red_green += filters.red_green.back();
        sum_blue_yellow_1 += filters.blue_yellow_1.back();
        sum_blue_yellow_2 += filters.blue_yellow_2.back();
    }
    // The 2D blue-yellow kernel is f1(x) f1(y) + f2(x) f2(y); its sum is S1^2 + S2^2.
    const float blue_yellow_norm = 1.0f / std::sqrt(sum_blue_yellow_1 * sum_blue_yellow_1 + sum_blue_yellow_2 * sum_blue_yellow_2);
    for (int i = 0; i < width; ++i) {
        filters.achromatic[i] /= sum_achromatic;
        filters.red_green[i] /= sum_red_green;
        filters.blue_yellow_1[i] *= blue_yellow_norm;
        filters.blue_yellow_2[i] *= blue_yellow_norm;
    }
    return filters;
}

struct FeatureFilters {
    int radius = 0;
    std::vector<float> gaussian, first_derivative, second_derivative;
};

FeatureFilters make_feature_filters(float ppd) {
    FeatureFilters filters;
    const float sigma = 0.5f * feature_width * ppd;
    filters.radius = int(std::ceil(3.0f * sigma));
    const int width = 2 * filters.radius + 1;
    float gaussian_sum = 0.0f, first_positive = 0.0f, first_negative = 0.0f, second_positive = 0.0f,
          second_negative = 0.0f;
    for (int i = 0; i < width; ++i) {
        const float x = float(i - filters.radius);
        const float g = std::exp(-(x * x) / (2.0f * sigma * sigma));
        const float dg = -x * g;
        const float ddg = (x * x / (sigma * sigma) - 1.0f) * g;
        gaussian_sum += g;
        (dg > 0.0f ? first_positive : first_negative) += std::abs(dg);
        (ddg > 0.0f ? second_positive : second_negative) += std::abs(ddg);
        filters.gaussian.push_back(g);
        filters.first_derivative.push_back(dg);
        filters.second_derivative.push_back(ddg);
    }
    // Gaussian sums to 1; each derivative's positive lobes to +1 and negative lobes to -1.
    for (int i = 0; i < width; ++i) {
        filters.gaussian[i] /= gaussian_sum;
        float& dg = filters.first_derivative[i];
        dg /= dg > 0.0f ? first_positive : first_negative;
        float& ddg = filters.second_derivative[i];
        ddg /= ddg > 0.0f ? second_positive : second_negative;
    }
    return filters;
}

// A float plane, width * height, row-major.
using Plane = std::vector<float>;

struct OpponentImage {
    Plane y, cx, cz;
};

OpponentImage to_opponent_space(const Image& image) {
    const size_t count = size_t(image.width) * size_t(image.height);
    OpponentImage out{Plane(count), Plane(count), Plane(count)};
    parallel_for(size_t(image.height), 0, [&](size_t index, int) {
        const int32_t y = int32_t(index);
        for (size_t i = size_t(y) * size_t(image.width), end = i + size_t(image.width); i < end; ++i) {
            const float* p = &image.pixels[i * 4];
            const Color ycxcz = xyz_to_ycxcz(linear_rgb_to_xyz(clamp01({p[0], p[1], p[2]})));
            out.y[i] = ycxcz.x;
            out.cx[i] = ycxcz.y;
            out.cz[i] = ycxcz.z;
        }
    });
    return out;
}

// Clamp-to-edge convolution along each row.
Plane convolve_rows(const Plane& source, const std::vector<float>& kernel, int width, int height) {
    Plane destination(source.size());
    const int radius = int(kernel.size() / 2);
    parallel_for(size_t(height), 0, [&](size_t index, int) {
        const int32_t y = int32_t(index);
        const float* row = &source[size_t(y) * size_t(width)];
        float* out = &destination[size_t(y) * size_t(width)];
        for (int x = 0; x < width; ++x) {
            float sum = 0.0f;
            if (x >= radius && x + radius < width) {  // interior: no clamping, vectorisable
                const float* window = row + (x - radius);
                for (size_t k = 0; k < kernel.size(); ++k) sum += kernel[k] * window[k];
            } else {
                for (int k = -radius; k <= radius; ++k)
                    sum += kernel[size_t(k + radius)] * row[std::clamp(x + k, 0, width - 1)];
            }
            out[x] = sum;
        }
    });
    return destination;
}

// Clamp-to-edge convolution along each column, accumulated one kernel tap (a whole row) at a time
// so the inner loop runs over contiguous memory.
Plane convolve_columns(const Plane& source, const std::vector<float>& kernel, int width, int height) {
    Plane destination(source.size(), 0.0f);
    const int radius = int(kernel.size() / 2);
    parallel_for(size_t(height), 0, [&](size_t index, int) {
        const int32_t y = int32_t(index);
        float* out = &destination[size_t(y) * size_t(width)];
        for (int k = -radius; k <= radius; ++k) {
            const float weight = kernel[size_t(k + radius)];
            const float* row = &source[size_t(std::clamp(y + k, 0, height - 1)) * size_t(width)];
            for (int x = 0; x < width; ++x) out[x] += weight * row[x];
        }
    });
    return destination;
}

Plane separable_filter(const Plane& source, const std::vector<float>& kernel_x, const std::vector<float>& kernel_y,
                       int width, int height) {
    return convolve_columns(convolve_rows(source, kernel_x, width, height), kernel_y, width, height);
}

// Colour pipeline output: CSF-filtered opponent image (blue-yellow as the sum of its two parts).
OpponentImage csf_filter(const OpponentImage& image, const SpatialFilters& filters, int width, int height) {
    OpponentImage out;
    out.y = separable_filter(image.y, filters.achromatic, filters.achromatic, width, height);
    out.cx = separable_filter(image.cx, filters.red_green, filters.red_green, width, height);
    out.cz = separable_filter(image.cz, filters.blue_yellow_1, filters.blue_yellow_1, width, height);
    const Plane second = separable_filter(image.cz, filters.blue_yellow_2, filters.blue_yellow_2, width, height);
    for (size_t i = 0; i < out.cz.size(); ++i) out.cz[i] += second[i];
    return out;
}

Color filtered_to_hunt_lab(const OpponentImage& image, size_t i) {
    const Color rgb = clamp01(xyz_to_linear_rgb(ycxcz_to_xyz({image.y[i], image.cx[i], image.cz[i]})));
    return hunt_adjusted_lab(xyz_to_lab(linear_rgb_to_xyz(rgb)));
}

// Edge and point strength of the normalised achromatic channel.
struct FeatureResponse {
    Plane edge, point;
};

FeatureResponse feature_response(const Plane& achromatic, const FeatureFilters& filters, int width, int height) {
    Plane gray(achromatic.size());
    for (size_t i = 0; i < gray.size(); ++i) gray[i] = (achromatic[i] + 16.0f) / 116.0f;  // to [0, 1]
    // x-derivative filters are derivative(x) * gaussian(y) and vice versa; the row passes are shared.
    const Plane rows_first = convolve_rows(gray, filters.first_derivative, width, height);
    const Plane rows_second = convolve_rows(gray, filters.second_derivative, width, height);
    const Plane rows_gaussian = convolve_rows(gray, filters.gaussian, width, height);
    const Plane dx = convolve_columns(rows_first, filters.gaussian, width, height);
    const Plane ddx = convolve_columns(rows_second, filters.gaussian, width, height);
    const Plane dy = convolve_columns(rows_gaussian, filters.first_derivative, width, height);
    const Plane ddy = convolve_columns(rows_gaussian, filters.second_derivative, width, height);
    FeatureResponse response{Plane(gray.size()), Plane(gray.size())};
    for (size_t i = 0; i < gray.size(); ++i) {
        response.edge[i] = std::sqrt(dx[i] * dx[i] + dy[i] * dy[i]);
        response.point[i] = std::sqrt(ddx[i] * ddx[i] + ddy[i] * ddy[i]);
    }
    return response;
}

}  // namespace

std::vector<float> compute_flip_map(const Image& test, const Image& reference, double pixels_per_degree) {
    if (!(pixels_per_degree > 0.0))
        throw std::invalid_argument(fmt::format("FLIP: pixels per degree must be positive, got {}", pixels_per_degree));
    const ComparablePair pair = make_comparable_pair(test, reference);
    const int width = test.width;
    const int height = test.height;
    const float ppd = float(pixels_per_degree);

    const OpponentImage test_opponent = to_opponent_space(pair.test);
    const OpponentImage reference_opponent = to_opponent_space(pair.reference);

    const SpatialFilters spatial = make_spatial_filters(ppd);
    const OpponentImage test_filtered = csf_filter(test_opponent, spatial, width, height);
    const OpponentImage reference_filtered = csf_filter(reference_opponent, spatial, width, height);

    const FeatureFilters features = make_feature_filters(ppd);
    const FeatureResponse test_features = feature_response(test_opponent.y, features, width, height);
    const FeatureResponse reference_features = feature_response(reference_opponent.y, features, width, height);

    const float c_max = max_colour_difference();
    const float breakpoint = p_c * c_max;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::vector<float> flip_map(size_t(width) * size_t(height));
    parallel_for(size_t(height), 0, [&](size_t index, int) {
        const int32_t y = int32_t(index);
        for (size_t i = size_t(y) * size_t(width), end = i + size_t(width); i < end; ++i) {
            if (!pair.included[i]) {
                flip_map[i] = nan;
                continue;
            }
            float colour_difference = std::pow(
                hyab(filtered_to_hunt_lab(reference_filtered, i), filtered_to_hunt_lab(test_filtered, i)), q_c);
            // Compress: [0, p_c c_max) -> [0, p_t), [p_c c_max, c_max] -> [p_t, 1].
            colour_difference = colour_difference < breakpoint
                                    ? colour_difference * (p_t / breakpoint)
                                    : p_t + ((colour_difference - breakpoint) / (c_max - breakpoint)) * (1.0f - p_t);

            const float edge_difference = std::abs(reference_features.edge[i] - test_features.edge[i]);
            const float point_difference = std::abs(reference_features.point[i] - test_features.point[i]);
            const float feature_difference =
                std::pow(std::max(edge_difference, point_difference) / std::sqrt(2.0f), q_f);

            flip_map[i] = std::pow(colour_difference, 1.0f - feature_difference);
        }
    });
    return flip_map;
}

FlipPooled pool_flip_map(const std::vector<float>& flip_map) {
    std::vector<float> values;
    values.reserve(flip_map.size());
    for (float v : flip_map)
        if (std::isfinite(v)) values.push_back(v);

    FlipPooled pooled;
    pooled.pooled_pixels = (long long)values.size();
    if (values.empty()) {
        pooled.mean = pooled.weighted_median = std::numeric_limits<double>::quiet_NaN();
        return pooled;
    }
    std::sort(values.begin(), values.end());
    double total = 0.0;
    for (float v : values) total += v;
    pooled.mean = total / double(values.size());

    pooled.weighted_median = 0.0;
    double running = 0.0;
    for (float v : values) {
        running += v;
        if (running > 0.5 * total) {
            pooled.weighted_median = v;
            break;
        }
    }
    return pooled;
}

}  // namespace canopy
