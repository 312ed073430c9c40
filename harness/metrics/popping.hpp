// Popping along a camera path ([camera_path] popping = true): how much more a technique's image
// changes from one frame to the next than the truth does. Per pair of consecutive frames k-1, k,
// over the pixels where all four images are finite, the mean of
//   | (L(T_k) - L(T_{k-1})) - (L(R_k) - L(R_{k-1})) |
// with T the technique's frames, R the reference's (ray-traced at each frame's camera) and L the
// Rec. 709 luminance of linear RGB. Camera motion changes both alike and cancels; what is left is
// what the technique changes that the scene does not: a representation switching at a LoD
// boundary, temporal aliasing (shared by every raster technique at the same sample count), and the
// reference's own sample noise re-drawn as the camera moves (shared by every technique: compare
// techniques with each other, not with zero).
#pragma once

#include "core/image.hpp"

#include <vector>

namespace canopy {

struct PoppingError {
    double mean = 0;  // over the frame pairs
    double max = 0;   // the worst pair's
    int worst_pair = 0;  // k of the worst pair (frames k-1, k)
    std::vector<double> per_pair;  // [k - 1] for k = 1 .. frames - 1
};

// `technique` and `reference` hold the same number (>= 2) of same-size frames, in path order.
// Throws std::invalid_argument otherwise.
PoppingError compute_popping(const std::vector<Image>& technique, const std::vector<const Image*>& reference);

}  // namespace canopy
