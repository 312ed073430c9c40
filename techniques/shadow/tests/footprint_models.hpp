// The visibility profile each shadow technique implies across the straight edge of
// edge_profile.hpp: its filter footprint over the rasterised edge, evaluated in closed form on
// the CPU. A model sees only the map the technique reads — an edge at t = boundary (texels from
// the geometric edge), blocker and receiver depths — and the technique's parameters; the
// visibility functions of the prefiltered family come from shadow_filtering.h, the code the
// shaders run. Nothing here reads the rendered image.
#pragma once

#include "edge_profile.hpp"
#include "../shaders/shadow_filtering.h"

#include "../common/poisson_disk.hpp"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace canopy::test {

// A nearest-texel lookup of the depth map at t: 1 on the lit side of the rasterised edge.
inline double nearest_lit(const EdgeScene& e, double t) { return t >= e.boundary ? 1.0 : 0.0; }

// A bilinear 2x2 depth compare at t: linear between the last blocked and the first lit texel centre.
inline double bilinear_lit(const EdgeScene& e, double t) { return std::clamp(t - e.boundary + 0.5, 0.0, 1.0); }

// Offset of tap i (along the map axis across the edge) of a k-wide grid spanning [-radius, radius]
// texels, as pcss.frag's spread_offset; the grid's other axis runs along the edge and changes nothing.
inline double spread(int i, int k, double radius) { return k > 1 ? (i - 0.5 * (k - 1)) * 2.0 * radius / (k - 1) : 0.0; }

// shadow.hard: one nearest texel.
inline double hard_model(const EdgeScene& e, const ProfileSample& s) { return nearest_lit(e, s.t); }

// shadow.pcf on a k x k texel grid (pattern = grid): the mean of k column lookups one texel apart.
inline double pcf_grid_model(const EdgeScene& e, const ProfileSample& s, int k, bool hardware) {
    double lit = 0.0;
    for (int i = 0; i < k; ++i) {
        const double t = s.t + (i - 0.5 * (k - 1));
        lit += hardware ? bilinear_lit(e, t) : nearest_lit(e, t);
    }
    return lit / k;
}

// shadow.pcf with pattern = poisson: k*k Poisson-disk taps of radius k/2 texels.
inline double pcf_poisson_model(const EdgeScene& e, const ProfileSample& s, int k) {
    const std::vector<std::array<float, 2>> disk = poisson_disk(k * k);  // pcf_shadows.cpp's set
    double lit = 0.0;
    for (const auto& o : disk) lit += nearest_lit(e, s.t + o[size_t(e.map_axis)] * 0.5 * k * e.map_direction);
    return lit / double(disk.size());
}

// The penumbra width of eq 6.1 for the slab over the floor, world units at the floor.
inline double eq61_width(const EdgeScene& e, double light_width) {
    return light_width * (e.receiver_distance - e.blocker_distance) / e.blocker_distance;
}

// shadow.pcss: a Bs-wide blocker search over the light's frustum cut at the near plane (no
// blocker: lit), then K-wide PCF over the eq 6.1 penumbra of the blockers found (all at the
// slab's depth).
inline double pcss_model(const EdgeScene& e, const ProfileSample& s, double light_width, int blocker_search, int kernel,
                         double max_radius = 64.0) {
    const double d_r = e.receiver_distance, near_plane = e.light_view.near_plane;
    const double search =
        std::clamp(0.5 * light_width * (d_r - near_plane) / (d_r * near_plane) / e.texel_image, 0.5, max_radius);
    bool blocked = false;
    for (int i = 0; i < blocker_search; ++i) blocked |= nearest_lit(e, s.t + spread(i, blocker_search, search)) == 0.0;
    if (!blocked) return 1.0;
    const double radius = std::clamp(0.5 * eq61_width(e, light_width) / (d_r * e.texel_image), 0.5, max_radius);
    double lit = 0.0;
    for (int i = 0; i < kernel; ++i) lit += nearest_lit(e, s.t + spread(i, kernel, radius));
    return lit / kernel;
}

// shadow.ssss: the hard shadow blurred in screen space by a separable Gaussian, K taps over
// +-3 sigma along image x, then K along image y over the first pass's result, every pixel with
// its own sigma: eq 6.2 at its own depth along the view axis, with the slab's depth as the
// (coarse) blocker depth and the width taken as the Gaussian's 10-90 % rise (2.563 sigma). The
// camera looks straight down, so the floor's view normal is the view axis and the kernel is
// round (no anisotropic shrink). Each tap reads a whole pixel, clamped to the image, at least one
// pixel from its neighbours, weighted by the Gaussian of its actual offset (the README's choice);
// pixels with sigma below 0.25 are left as they are. Every tap lies on the floor, the centre's
// tangent plane, so the depth test keeps them all; the coarse map's dilation is assumed to reach
// the whole penumbra. The profile is the mean over the middle half of the image across it, as
// profile_from_image takes it.
inline Profile ssss_model(const EdgeScene& e, const Profile& at, double light_width, int kernel) {
    const int width = e.image_width, height = e.image_height;
    std::vector<double> hard(size_t(width) * height), sigma(hard.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Ray r = primary_ray(e.scene.camera, width, height, float(x) + 0.5f, float(y) + 0.5f);
            const glm::dvec3 origin(r.origin), direction(r.direction);
            const glm::dvec3 p = origin + direction * (-origin.y / direction.y);  // on the floor
            const size_t i = size_t(y) * width + size_t(x);
            hard[i] = nearest_lit(e, edge_t(e, glm::vec3(p)));
            const glm::dvec3 forward = glm::normalize(glm::dvec3(e.scene.camera.target - e.scene.camera.position));
            sigma[i] = eq61_width(e, light_width) / glm::dot(p - origin, forward) * e.focal_pixels / 2.563;  // eq 6.2 at depth Z, pixels
        }
    // One pass over `in` along (dx, dy).
    auto pass = [&](const std::vector<double>& in, int dx, int dy) {
        std::vector<double> out(in.size());
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const size_t c = size_t(y) * width + size_t(x);
                const double s = sigma[c];
                if (s < 0.25) {
                    out[c] = in[c];
                    continue;
                }
                const double spacing = kernel > 1 ? std::max(6.0 * s / (kernel - 1), 1.0) : 0.0;
                double sum = 0.0, weights = 0.0;
                for (int i = 0; i < kernel; ++i) {
                    const double exact = (i - 0.5 * (kernel - 1)) * spacing;
                    const int offset = int(std::copysign(std::floor(std::abs(exact) + 0.5), exact));  // whole pixels
                    const int tx = std::clamp(x + offset * dx, 0, width - 1), ty = std::clamp(y + offset * dy, 0, height - 1);
                    const double w = std::exp(-0.5 * double(offset) * offset / (s * s));
                    sum += w * in[size_t(ty) * width + size_t(tx)];
                    weights += w;
                }
                out[c] = sum / weights;
            }
        return out;
    };
    const std::vector<double> blurred = pass(pass(hard, 1, 0), 0, 1);
    const bool columns = e.setup.across_z;  // the profile runs down the image
    const int breadth = columns ? width : height;
    Profile out = at;
    for (size_t i = 0; i < out.size(); ++i) {
        double sum = 0.0;
        for (int j = breadth / 4; j < 3 * breadth / 4; ++j)
            sum += columns ? blurred[i * width + size_t(j)] : blurred[size_t(j) * width + i];
        out[i].visibility = sum / (3 * breadth / 4 - breadth / 4);
    }
    return out;
}

// How a prefiltered technique turns depth into stored statistics, filters them, and reads them.
struct MomentModel {
    enum class Filter { box, min_max_mean, log_box };
    Filter filter = Filter::box;
    glm::dvec4 (*statistics)(double z, const std::array<double, 4>& p) = nullptr;
    double (*visibility)(const glm::dvec4& filtered, double z_r, const std::array<double, 4>& p) = nullptr;
    std::array<double, 4> params{};  // technique parameters the two functions use
};

// The prefiltered family: statistics of the rasterised map (blocker depth for texels left of the
// boundary), a separable `filter`-wide window (even widths round up, as prefilter_params says),
// then the bilinear lookup of the moment map at t; min and max combine as min and max.
inline double moment_model(const EdgeScene& e, const ProfileSample& s, const MomentModel& m, int filter) {
    const int r = filter / 2, width = 2 * r + 1;
    const double z_b = e.blocker_depth, z_r = e.receiver_depth;
    const glm::dvec4 blocker = m.statistics(z_b, m.params), receiver = m.statistics(z_r, m.params);
    // Filtered texel k (k = 0: the first texel on the lit side) covers texels k-r .. k+r.
    auto texel = [&](long k) {
        const double n = double(std::clamp(long(r) - k, 0L, long(width)));  // blocked texels in the window
        const double f = n / width;
        switch (m.filter) {
            case MomentModel::Filter::box: return f * blocker + (1.0 - f) * receiver;
            case MomentModel::Filter::min_max_mean:
                return glm::dvec4(n > 0 ? z_b : z_r, n < width ? z_r : z_b, f * z_b + (1.0 - f) * z_r, 1.0);
            case MomentModel::Filter::log_box:
                return glm::dvec4(std::log(f * std::exp(blocker.x) + (1.0 - f) * std::exp(receiver.x)), 0, 0, 1);
        }
        return receiver;
    };
    const double q = s.t - e.boundary - 0.5;  // in texel-centre units
    const long k0 = long(std::floor(q));
    const double a = q - double(k0);
    const glm::dvec4 t0 = texel(k0), t1 = texel(k0 + 1);
    glm::dvec4 looked_up;
    switch (m.filter) {
        case MomentModel::Filter::box: looked_up = (1.0 - a) * t0 + a * t1; break;
        case MomentModel::Filter::min_max_mean:
            looked_up = glm::dvec4(std::min(t0.x, t1.x), std::max(t0.y, t1.y), (1.0 - a) * t0.z + a * t1.z, 1.0);
            break;
        case MomentModel::Filter::log_box:  // log-space interpolation of the log-space means
            looked_up = glm::dvec4(std::log((1.0 - a) * std::exp(t0.x) + a * std::exp(t1.x)), 0, 0, 1);
            break;
    }
    return m.visibility(looked_up, z_r, m.params);
}

// The models of each prefiltered technique at its defaults (parameters in `params`).
namespace moments {

inline glm::dvec4 depth_and_square(double z, const std::array<double, 4>&) { return {z, z * z, 0.0, 1.0}; }

inline MomentModel vsm(double min_variance = 1e-5) {
    return {MomentModel::Filter::box, depth_and_square,
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>& p) {
                return double(shader::chebyshev_upper_bound(glm::vec2(m.x, m.y), float(z_r), float(p[0])));
            },
            {min_variance}};
}

inline MomentModel gauss_cdf(double min_variance = 1e-5) {
    return {MomentModel::Filter::box, depth_and_square,
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>& p) {
                return double(shader::gaussian_cdf_visibility(glm::vec2(m.x, m.y), float(z_r), float(p[0]), false));
            },
            {min_variance}};
}

// ESM: exp(c z) filtered linearly, or c z filtered in log space (log_space = true): both mean
// the log of the filtered exp(c z), which the model keeps in log space so nothing overflows.
inline MomentModel esm(double c = 80.0) {
    return {MomentModel::Filter::log_box, [](double z, const std::array<double, 4>& p) { return glm::dvec4(p[0] * z, 0, 0, 1); },
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>& p) {
                return double(shader::esm_visibility_log(float(m.x), float(z_r), float(p[0])));
            },
            {c}};
}

inline MomentModel power_cdf() {
    return {MomentModel::Filter::min_max_mean, depth_and_square,
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>&) {
                // The lit pass lowers the receiver by two float ulps (power_cdf.frag).
                return double(shader::power_cdf_visibility(float(m.x), float(m.y), float(m.z), float(z_r) * (1.0f - 0x1p-23f)));
            },
            {}};
}

inline MomentModel evsm(int components = 4, double c_pos = 40.0, double c_neg = 5.0, double min_variance = 1e-5) {
    return {MomentModel::Filter::box,
            [](double z, const std::array<double, 4>& p) {
                return glm::dvec4(shader::evsm_moments(float(z), float(p[0]), float(p[1])));
            },
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>& p) {
                const glm::vec4 f(m);
                return p[3] > 3.0 ? double(shader::evsm4_visibility(f, float(z_r), float(p[0]), float(p[1]), float(p[2])))
                                  : double(shader::evsm2_visibility(glm::vec2(f.x, f.y), float(z_r), float(p[0]), float(p[2])));
            },
            {c_pos, c_neg, min_variance, double(components)}};
}

inline MomentModel msm(double moment_bias = 3e-5) {
    return {MomentModel::Filter::box,
            [](double z, const std::array<double, 4>&) { return glm::dvec4(shader::msm_encode(float(z))); },
            [](const glm::dvec4& m, double z_r, const std::array<double, 4>& p) {
                return double(shader::msm_hamburger_visibility(shader::msm_decode(glm::vec4(m)), float(z_r), float(p[0])));
            },
            {moment_bias}};
}

}  // namespace moments

}  // namespace canopy::test
