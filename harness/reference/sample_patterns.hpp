// Deterministic random numbers and stratified 2D sample patterns for the reference renderer.
// Everything is a pure function of (seed, pixel, sample, light), so images do not depend on
// the thread count or the order in which tiles run.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace canopy {

// splitmix64's finaliser: a bijective 64-bit mix with good avalanche.
uint64_t mix_bits(uint64_t value);

// Hash of a sequence of integers, e.g. random_key(seed, pixel, sample, light).
template <class... Values>
uint64_t random_key(uint64_t first, Values... rest) {
    uint64_t key = mix_bits(first + 0x9e3779b97f4a7c15ull);
    ((key = mix_bits(key ^ (uint64_t(rest) + 0x9e3779b97f4a7c15ull))), ...);
    return key;
}

// Two independent uniform numbers in [0, 1) from one 64-bit key (24 bits each).
glm::vec2 unit_pair(uint64_t key);

// Kensler's correlated multi-jittered sampling ("Correlated Multi-Jittered Sampling", Pixar
// 2013): point `index` of `count` in [0,1)^2. The set is stratified on an m x n grid
// (m/n ~ aspect) and in both 1D projections; `pattern` selects an independent permutation.
glm::vec2 cmj_sample(uint32_t index, uint32_t count, uint32_t pattern, float aspect = 1.0f);

// A fixed collection of CMJ point sets of one size, precomputed because generating CMJ points
// per shadow ray costs as much as a short ray. Each use picks a set and shifts it by a random
// toroidal offset (Cranley-Patterson rotation): every shifted point is uniform on [0,1)^2, so
// the estimate stays unbiased, and the shifted set is still one point per (shifted) stratum.
// Stored as structure-of-arrays, each set padded to a multiple of 16 points, so that a packet's
// worth of samples is generated with SIMD; also stores cos and sin of 2 pi y for samplers that
// use y as an azimuth (a shift of y is then a rotation, applied without trigonometry).
class StratifiedPatterns {
public:
    struct Set {
        const float* x;
        const float* y;
        const float* cos_azimuth;  // cos(2 pi y)
        const float* sin_azimuth;  // sin(2 pi y)
    };

    StratifiedPatterns() = default;
    StratifiedPatterns(int sample_count, float aspect, uint64_t seed, int pattern_count = 64);

    int sample_count() const { return sample_count_; }
    // The base points of the set chosen by `key` (sample_count() of them, readable up to the
    // next multiple of 16).
    Set set(uint64_t key) const {
        const size_t offset = size_t(key % uint64_t(pattern_count_)) * size_t(stride_);
        return {&x_[offset], &y_[offset], &cos_[offset], &sin_[offset]};
    }

private:
    int sample_count_ = 0;
    int pattern_count_ = 0;
    int stride_ = 0;  // sample_count_ rounded up to a multiple of 16
    std::vector<float> x_, y_, cos_, sin_;
};

}  // namespace canopy
