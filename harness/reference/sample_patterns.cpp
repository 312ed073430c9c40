#include "reference/sample_patterns.hpp"

#include <algorithm>
#include <cmath>

namespace canopy {

uint64_t mix_bits(uint64_t value) {
    value ^= value >> 30;
    value *= 0xbf58476d1ce4e5b9ull;
    value ^= value >> 27;
    value *= 0x94d049bb133111ebull;
    value ^= value >> 31;
    return value;
}

glm::vec2 unit_pair(uint64_t key) {
    constexpr float kScale = 1.0f / float(1u << 24);
    return {float(uint32_t(key >> 40)) * kScale, float(uint32_t(key >> 8) & 0xffffffu) * kScale};
}

namespace {

// Kensler's hash-based permutation of [0, length): cycle-walks a bijection on the next power of two.
uint32_t permute(uint32_t index, uint32_t length, uint32_t pattern) {
    uint32_t mask = length - 1;
    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do {
        index ^= pattern;
        index *= 0xe170893du;
        index ^= pattern >> 16;
        index ^= (index & mask) >> 4;
        index ^= pattern >> 8;
        index *= 0x0929eb3fu;
        index ^= pattern >> 23;
        index ^= (index & mask) >> 1;
        index *= 1u | pattern >> 27;
        index *= 0x6935fa69u;
        index ^= (index & mask) >> 11;
        index *= 0x74dcb303u;
        index ^= (index & mask) >> 2;
        index *= 0x9e501cc3u;
        index ^= (index & mask) >> 2;
        index *= 0xc860a3dfu;
        index &= mask;
        index ^= index >> 5;
    } while (index >= length);
    return (index + pattern) % length;
}

// Kensler's hashed float in [0, 1).
float hashed_unit(uint32_t index, uint32_t pattern) {
    index ^= pattern;
    index ^= index >> 17;
    index ^= index >> 10;
    index *= 0xb36534e5u;
    index ^= index >> 12;
    index ^= index >> 21;
    index *= 0x93fc4795u;
    index ^= 0xdf6e307fu;
    index ^= index >> 17;
    index *= 1u | pattern >> 18;
    return std::min(float(index) * (1.0f / 4294967808.0f), 0x1.fffffep-1f);
}

}  // namespace

glm::vec2 cmj_sample(uint32_t index, uint32_t count, uint32_t pattern, float aspect) {
    const uint32_t columns = std::clamp(uint32_t(std::sqrt(float(count) * aspect)), 1u, count);
    const uint32_t rows = (count + columns - 1) / columns;
    const uint32_t s = permute(index, count, pattern * 0x51633e2du);
    const uint32_t sx = permute(s % columns, columns, pattern * 0x68bc21ebu);
    const uint32_t sy = permute(s / columns, rows, pattern * 0x02e5be93u);
    const float jx = hashed_unit(s, pattern * 0x967a889bu);
    const float jy = hashed_unit(s, pattern * 0x368cc8b7u);
    const float x = (float(sx) + (float(sy) + jx) / float(rows)) / float(columns);
    const float y = (float(s) + jy) / float(count);
    return {std::min(x, 0x1.fffffep-1f), std::min(y, 0x1.fffffep-1f)};
}

StratifiedPatterns::StratifiedPatterns(int sample_count, float aspect, uint64_t seed, int pattern_count)
    : sample_count_(std::max(sample_count, 1)), pattern_count_(std::max(pattern_count, 1)) {
    constexpr float kTwoPi = 6.28318530717958647692f;
    stride_ = (sample_count_ + 15) / 16 * 16;
    const size_t total = size_t(stride_) * size_t(pattern_count_);
    x_.assign(total, 0.0f);
    y_.assign(total, 0.0f);
    cos_.assign(total, 1.0f);
    sin_.assign(total, 0.0f);
    for (int pattern = 0; pattern < pattern_count_; ++pattern) {
        const uint32_t pattern_id = uint32_t(random_key(seed, uint64_t(pattern)));
        for (int i = 0; i < sample_count_; ++i) {
            const glm::vec2 point = cmj_sample(uint32_t(i), uint32_t(sample_count_), pattern_id, aspect);
            const size_t at = size_t(pattern) * size_t(stride_) + size_t(i);
            x_[at] = point.x;
            y_[at] = point.y;
            cos_[at] = std::cos(kTwoPi * point.y);
            sin_[at] = std::sin(kTwoPi * point.y);
        }
    }
}

}  // namespace canopy
