// How much work the Embree reference renderer does per pixel.
#pragma once

#include <cstdint>

namespace canopy {

struct ReferenceSettings {
    int light_samples = 256;  // shadow rays per pixel sample for area lights (1 for point-like lights)
    int pixel_samples = 4;    // stratified (correlated multi-jittered) sub-pixel samples per pixel
    uint64_t seed = 1;
    int threads = 0;          // 0 = all cores; the image does not depend on it
};

}  // namespace canopy
