#include "run/case_labels.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace canopy {

std::string case_name(const std::string& technique, const std::string& parameters) {
    return parameters.empty() || parameters == "-" ? technique : technique + " " + parameters;
}

CaseLabels::CaseLabels(const std::vector<Case>& cases, const TechniqueRegistry& registry) : registry_(registry) {
    for (const Case& c : cases) add(c.technique, c.params.values());
}

CaseLabels::CaseLabels(const std::vector<CaseResult>& cases, const TechniqueRegistry& registry) : registry_(registry) {
    for (const CaseResult& c : cases) add(c.technique, c.params);
}

void CaseLabels::add(const std::string& technique, const Values& values) {
    for (const auto& [name, value] : values) values_[technique][name].insert(to_string(value));
}

bool CaseLabels::swept(const std::string& technique, const std::string& parameter) const {
    const auto technique_values = values_.find(technique);
    if (technique_values == values_.end()) return false;
    const auto parameter_values = technique_values->second.find(parameter);
    return parameter_values != technique_values->second.end() && parameter_values->second.size() > 1;
}

std::string CaseLabels::parameters(const Case& c) const { return parameters(c.technique, c.params.values()); }
std::string CaseLabels::parameters(const CaseResult& c) const { return parameters(c.technique, c.params); }
std::string CaseLabels::label(const CaseResult& c) const { return case_name(c.technique, parameters(c)); }

std::string CaseLabels::parameters(const std::string& technique_name, const Values& values) const {
    const Technique* technique = registry_.find(technique_name);
    const std::vector<ParamSpec> specs = technique ? technique->params() : std::vector<ParamSpec>{};
    std::string out;
    for (const auto& [name, value] : values) {
        const auto spec = std::find_if(specs.begin(), specs.end(), [&name = name](const ParamSpec& s) { return s.name == name; });
        const bool is_default = spec != specs.end() && to_string(spec->default_value) == to_string(value);
        if (is_default && !swept(technique_name, name)) continue;
        out += fmt::format("{}{}={}", out.empty() ? "" : " ", name, to_string(value));
    }
    return out.empty() ? "-" : out;
}

}  // namespace canopy
