// What every grass representation shares in its error columns: it replaces the blades the
// reference traces (the primary hits change), so the shadow family's visibility and region columns
// do not apply; besides the whole-image errors it declares the population coverage (its colour
// target's alpha: the ground and the background write 0, the blades 1, alpha-to-coverage keeps the
// covered samples' share), against the reference's samples that hit a blade.
#pragma once

#include "core/error_columns.hpp"

#include <array>
#include <string>
#include <vector>

namespace canopy::grass {

inline constexpr ErrorColumns kGrassErrorColumns{.coverage = true};

// The Pareto fronts' default error axes (report/pareto.hpp): the whole image's FLIP and RMSE (in a
// local-mode run: the representation's error, no blade shadowing) and the coverage error over 8x8
// tiles (where the grass is, pixel-scale aliasing averaged out).
inline std::vector<std::string> pareto_errors() { return {"flip_mean", "rmse", "coverage_tile_mae"}; }

// The colour target's clear: the harness fills in the background's radiance; alpha 0, no blade.
inline constexpr std::array<float, 4> kUncoveredClear{0.0f, 0.0f, 0.0f, 0.0f};

}  // namespace canopy::grass
