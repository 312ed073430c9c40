// Reads a results.json back into a RunRecord, so a run can be continued (--resume) and an output
// folder's owner checked. Numbers come back exactly as they were measured (JSON keeps every digit).
#pragma once

#include "run/case_result.hpp"

#include <filesystem>

namespace canopy {

// Throws std::runtime_error "cannot read FILE: reason" when the file is missing, is not JSON or is
// not a results.json of this version (kResultsVersion). The cases' params come back in name order
// and params_summary / params_shown are empty: the runner rebuilds them from its own cases.
RunRecord read_json_report(const std::filesystem::path& file);

}  // namespace canopy
