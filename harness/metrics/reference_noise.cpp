#include "metrics/reference_noise.hpp"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

namespace canopy {

namespace {

uint64_t splitmix64(uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

// Two independent uniforms in (0, 1] from one counter, then Box-Muller: written out so the noise
// is the same with every standard library.
double standard_normal(uint64_t counter) {
    const uint64_t a = splitmix64(counter), b = splitmix64(a ^ 0xD1B54A32D192ED03ull);
    const double u1 = (double(a >> 11) + 1.0) * 0x1.0p-53, u2 = double(b >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

}  // namespace

Image perturbed_reference(const Image& radiance, const Image& variance, int replicate) {
    if (radiance.width != variance.width || radiance.height != variance.height)
        throw std::invalid_argument("the reference's variance image differs in size from its radiance");
    Image out = radiance;
    const uint64_t base = splitmix64(uint64_t(replicate) + 1) << 2;
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        if (i % 4 == 3) continue;  // alpha
        const float v = variance.pixels[i];
        if (!(v > 0.0f) || !std::isfinite(v)) continue;
        out.pixels[i] += float(std::sqrt(double(v)) * standard_normal(base + i * 0x9E3779B97F4A7C15ull));
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
