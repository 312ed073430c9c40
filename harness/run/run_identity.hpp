// What a run's cases, images and errors depend on, apart from the timing noise: the experiment,
// its config (content hash), the run options, the device and the build. Two runs with the same
// identity measure the same cases the same way, so one may continue the other (--resume), and an
// output folder is only ever shared by runs of one identity.
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace canopy {

struct Environment;
struct Experiment;
struct RunOptions;

struct RunIdentity {
    // (name, value) in a fixed order, e.g. ("config_hash", "9f0c..."), ("quick", "true").
    // Adding a run option that changes results (a config override, ...) is one more field.
    std::vector<std::pair<std::string, std::string>> fields;
    // The names of those fields the command line decides (--quick, --images, ...; the timing
    // settings through --quick): a run with the same options could match them. Not recorded.
    std::vector<std::string> set_by_options;

    const std::string* find(const std::string& name) const;
};

RunIdentity make_run_identity(const Experiment& experiment, const RunOptions& options, const Environment& environment);

// One line per field that differs, "quick: the folder's run has true, this one false"; empty
// when `recorded` (read from a results.json) and `now` match.
std::vector<std::string> identity_differences(const RunIdentity& recorded, const RunIdentity& now);

// Whether `recorded` and `now` differ, and only in fields `now` has from the command line: then
// running with the recorded run's options continues it.
bool only_options_differ(const RunIdentity& recorded, const RunIdentity& now);

}  // namespace canopy
