// Whether an experiment changed since a run only in what it claims of the paper: its [paper]
// table (claims, their rules, notes) decides no measurement, so a recorded run may be judged
// again under the new table (`canopy export-paper --rejudge`) without measuring again.
#pragma once

#include "config/experiment.hpp"

#include <string>

namespace canopy {

// "" when `text_at_run` (the experiment file as the run's commit had it) hashes with the
// experiment's files to `recorded_hash` — the run measured exactly that text and those scenes —
// and it parses to the same tables as the experiment's file now, [paper] left out. Otherwise what
// differs, in words.
std::string paper_table_only_change(const Experiment& now, const std::filesystem::path& file_now,
                                    const std::string& text_at_run, const std::string& recorded_hash);

}  // namespace canopy
