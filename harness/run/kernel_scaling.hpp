// The kernel-size scaling benchmark: per method, time of the passes its kernel affects against
// kernel width, fitted as t = a + b * width^p. Separable filters should give p near 1, PCF and
// PCSS (K x K taps) near 2. A benchmark, not a test: nothing here asserts a speed.
#pragma once

#include "core/registry.hpp"
#include "gpu/context.hpp"
#include "run/environment.hpp"

#include <string>
#include <vector>

namespace canopy {

struct PowerFit {
    double offset = 0, scale = 0, exponent = 0;  // t = offset + scale * width^exponent
    double r_squared = 0;
};

// Least squares over exponents in [0.2, 3.5] (step 0.005), linear in offset and scale for each,
// with the offset constrained to be non-negative (a fixed per-pass cost).
PowerFit fit_power_law(const std::vector<double>& widths, const std::vector<double>& times);

struct ScalingSeries {
    std::string technique;
    std::string parameter;             // the swept parameter
    std::vector<std::string> passes;   // the passes whose times are summed
    std::vector<double> widths, median_ms, mad_ms;
    PowerFit fit;
    double expected_exponent = 0;      // 1 separable, 2 for K x K
};

struct ScalingOptions {
    std::string scene_file;
    int width = 640, height = 360;
    int warmup = 2, measured = 30;  // rounds: every width of a technique renders one frame per round
    bool show_progress = true;
};

std::vector<ScalingSeries> run_kernel_scaling(const TechniqueRegistry& registry, const GpuContext& gpu,
                                              const ScalingOptions& options);
std::string kernel_scaling_report(const std::vector<ScalingSeries>& series, const Environment& environment,
                                  const ScalingOptions& options);

}  // namespace canopy
