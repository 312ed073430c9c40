#include "reference/reference_noise.hpp"

#include "reference/sample_patterns.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace canopy {

namespace {

// A standard normal number from one key, by Box-Muller over unit_pair's two uniforms (written out,
// so the noise is the same with every standard library).
double standard_normal(uint64_t key) {
    const glm::vec2 u = unit_pair(key);
    return std::sqrt(-2.0 * std::log(1.0 - double(u.x))) * std::cos(6.283185307179586 * double(u.y));
}

}  // namespace

Image perturbed_reference(const Image& radiance, const Image& variance, int replicate) {
    if (radiance.width != variance.width || radiance.height != variance.height)
        throw std::invalid_argument("the reference's variance image differs in size from its radiance");
    Image out = radiance;
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        const float v = variance.pixels[i];
        if (!(v > 0.0f) || !std::isfinite(v)) continue;
        out.pixels[i] += float(std::sqrt(double(v)) * standard_normal(random_key(uint64_t(replicate), uint64_t(i))));
    }
    return out;
}

double replicate_spread(const std::vector<double>& values) {
    double sum = 0, squares = 0;
    size_t n = 0;
    for (double v : values)
        if (std::isfinite(v)) sum += v, ++n;
    if (n < 2) return std::numeric_limits<double>::quiet_NaN();
    const double mean = sum / double(n);
    for (double v : values)
        if (std::isfinite(v)) squares += (v - mean) * (v - mean);
    return std::sqrt(squares / double(n - 1));
}

}  // namespace canopy
