// An experiment run as the integration tests run it: prepared and measured on the test GPU, no
// progress, no images, its references cached beside the output.
#pragma once

#include "config/experiment.hpp"
#include "run/case_result.hpp"

#include <filesystem>

namespace canopy::test {

RunRecord quiet_run(const Experiment& experiment, const std::filesystem::path& out_dir,
                    const std::filesystem::path& reference_cache_dir);

}  // namespace canopy::test
