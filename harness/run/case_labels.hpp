// How a case's parameters are shown in tables and progress lines: every swept parameter — one
// that takes more than one value among the experiment's cases of that technique, so rows can be
// told apart even where a value is the default — and every other value that differs from its
// default ("kernel=3 pattern=poisson").
#pragma once

#include "config/experiment.hpp"
#include "core/registry.hpp"
#include "run/case_result.hpp"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace canopy {

// A case's name in headings and "dominated by" cells: its technique, then its shown parameters
// unless they are "-" or empty ("shadow.hard", never "shadow.hard -").
std::string case_name(const std::string& technique, const std::string& parameters);

class CaseLabels {
public:
    CaseLabels(const std::vector<Case>& cases, const TechniqueRegistry& registry);
    // The cases of a recorded run (a results.json read back: report/json_record_reader.hpp).
    CaseLabels(const std::vector<CaseResult>& cases, const TechniqueRegistry& registry);

    // "kernel=3 resolution=256" in the order of `c`'s values; "-" when nothing is shown.
    std::string parameters(const Case& c) const;
    std::string parameters(const CaseResult& c) const;
    bool swept(const std::string& technique, const std::string& parameter) const;
    // "shadow.pcf kernel=3"; just "shadow.hard" when no parameter is shown (case_name).
    std::string label(const CaseResult& c) const;

private:
    using Values = std::vector<std::pair<std::string, ParamValue>>;
    void add(const std::string& technique, const Values& values);
    std::string parameters(const std::string& technique, const Values& values) const;

    const TechniqueRegistry& registry_;
    std::map<std::string, std::map<std::string, std::set<std::string>>> values_;  // technique -> parameter -> values
};

}  // namespace canopy
