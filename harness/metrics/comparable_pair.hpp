// A test/reference image pair prepared for comparison: same size checked, non-finite pixels
// neutralised so that every metric can run over the finite pixels only.
#pragma once

#include "core/image.hpp"

#include <cstdint>
#include <vector>

namespace canopy {

// True when all four channels (RGBA) of pixel (x, y) are finite.
bool pixel_is_finite(const Image& image, int x, int y);

// Number of pixels with a NaN or Inf in any channel (RGBA).
long long count_nonfinite_pixels(const Image& image);

// Throws std::invalid_argument unless both images are non-empty, have the same size and hold
// width * height * 4 floats. `what` names the comparison in the message.
void require_same_size(const Image& a, const Image& b, const char* what);

// Why this exists: a single NaN would otherwise turn every mean, every blurred SSIM window and every
// FLIP filter footprint it touches into NaN. A pixel is *excluded* when the test or the reference
// pixel has a non-finite channel. In the copies below an excluded pixel is made error-free: the
// test pixel takes the reference value (or both become black when the reference itself is bad),
// and `included[i]` is 0 so that pooled statistics skip it.
struct ComparablePair {
    Image test;
    Image reference;
    std::vector<std::uint8_t> included;  // width * height, row-major, 1 = both pixels finite
    long long included_count = 0;
};

ComparablePair make_comparable_pair(const Image& test, const Image& reference);

}  // namespace canopy
