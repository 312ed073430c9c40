// Poisson-disk sample sets for filter kernels (best-candidate dart throwing, Mitchell 1991).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace canopy {

// `count` points in the unit disk, deterministic for a given seed, no two closer than a
// best-candidate set allows. Ordered so that any prefix is itself well spread.
std::vector<std::array<float, 2>> poisson_disk(int count, uint32_t seed = 1);

}  // namespace canopy
