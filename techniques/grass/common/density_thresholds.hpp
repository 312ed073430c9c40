// Each blade's density threshold (Lemme 2012 §4.1.3, Boulanger 2008 §4.3.1): a blade is drawn
// where the local density is at least its threshold, so thinning the field to density d keeps
// the blades whose threshold is <= d. Thresholds lie in ]0, 1] (Lemme throughout; Boulanger says
// ]0, 1] at L925 and [0, 1] at L930: canopy takes ]0, 1], so density 0 draws nothing).
#pragma once

#include "../shaders/grass_density.h"
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace canopy::grass {

enum class ThresholdDistribution {
    uniform,    // independent and uniform (Lemme eq 4.3)
    clustered,  // around histogram-equalised low-frequency noise at the root (eq 4.4-4.6)
};

struct ThresholdParams {
    ThresholdDistribution distribution = ThresholdDistribution::uniform;
    // clustered: the Gaussian's spread around the noise (Lemme Fig 4.3: 0.12 "slightly", 0
    // "strongly" clustered; 0 gives every blade its noise value).
    float sigma = 0.12f;
    // clustered: noise periods across the patch. Lemme says "low frequency" only; the noise
    // repeats with the patch, so tiled patches show no seam.
    uint32_t noise_periods = 3;
    // canopy's addition, off by default: replace the thresholds by their ranks (i / N) so that
    // exactly d N blades are drawn at density d, keeping which blades go first. Lemme's scheme
    // is only roughly uniform for sigma > 0 (test_density_thresholds measures by how much).
    bool equalise = false;
};

// Whether a blade with this threshold is drawn at this local density (Lemme eq 5.22:
// kept when bdth <= ld; Boulanger L925: "strictly greater ... eliminated").
inline bool drawn_at_density(float threshold, float density) { return shader::grass_blade_drawn(threshold, density); }

// Periodic 2D gradient (Perlin) noise over the unit square, `periods` lattice cells across, so
// noise(p) == noise(p + (1, 0)) == noise(p + (0, 1)). Roughly in [-1, 1], 0 at lattice points.
float periodic_gradient_noise(glm::vec2 p, uint32_t periods, uint64_t seed);

// Histogram equalisation of a sample: each value's rank, (rank + 1) / N, in ]0, 1]; equal values
// are ranked by index. Uniform over the sample whatever the values' distribution.
std::vector<float> equalised_ranks(std::span<const float> values);

// One threshold per root (x and z in [0, 1); y ignored), deterministic in `seed`.
std::vector<float> density_thresholds(const ThresholdParams& params, std::span<const glm::vec3> roots, uint64_t seed);

}  // namespace canopy::grass
