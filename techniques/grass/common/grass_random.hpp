// The grass family's random numbers: a splitmix64 hash of (seed, item, draw), so item i's numbers
// do not depend on how many items there are, and the same on every standard library.
#pragma once

#include "reference/sample_patterns.hpp"

#include <cstdint>

namespace canopy::grass {

// 24 random bits of draw `draw` of item `item`.
inline uint32_t random_bits24(uint64_t seed, uint64_t item, uint64_t draw) {
    return uint32_t(random_key(seed, item, draw) >> 40);
}

// 24 bits as a number in [0, 1) and in ]0, 1]; both exact in float.
constexpr float unit_from_bits(uint32_t bits24) { return float(bits24) * (1.0f / 16777216.0f); }
constexpr float open_closed_from_bits(uint32_t bits24) { return float(16777216u - bits24) * (1.0f / 16777216.0f); }

inline float unit_random(uint64_t seed, uint64_t item, uint64_t draw) {
    return unit_from_bits(random_bits24(seed, item, draw));
}
inline float unit_random_open_closed(uint64_t seed, uint64_t item, uint64_t draw) {
    return open_closed_from_bits(random_bits24(seed, item, draw));
}

}  // namespace canopy::grass
