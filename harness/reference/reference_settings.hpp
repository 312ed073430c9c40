// How much work the Embree reference renderer does per pixel.
#pragma once

#include <cstdint>

namespace canopy {

// The rows of the image a render computes, [begin, end) (end -1: to the last row); the others stay
// 0. Every pixel is computed from its own rays and samples, so a reference rendered as row bands
// (`canopy reference --tile i/N`) and put together equals one rendered whole, bit for bit. Not part
// of a cache key: a band is never cached.
struct RowBand {
    int begin = 0, end = -1;
    bool whole() const { return begin == 0 && end < 0; }
};

struct ReferenceSettings {
    int light_samples = 256;  // shadow rays per pixel sample for area lights (1 for point-like lights)
    int pixel_samples = 4;    // stratified (correlated multi-jittered) sub-pixel samples per pixel
    uint64_t seed = 1;
    int threads = 0;          // 0 = all cores; the image does not depend on it
    RowBand rows;             // the whole image unless rendering a tile
};

}  // namespace canopy
