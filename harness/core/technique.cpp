#include "core/technique.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

namespace canopy {

std::optional<ParamConflict> Technique::conflict(const ParamSet&) const { return std::nullopt; }

std::vector<std::string> Technique::pareto_errors() const { return {"flip_mean"}; }

ParamSet resolve_params(const Technique& technique, const std::vector<ParamSpec>& specs,
                        const std::map<std::string, ParamValue>& given, const std::map<std::string, int>& given_lines,
                        const SourceLocation& where) {
    ParamSet params = ParamSet::resolve(specs, given, given_lines, where, technique.name());
    const std::optional<ParamConflict> conflict = technique.conflict(params);
    if (!conflict) return params;
    SourceLocation location = where;
    for (const std::string& name : conflict->params) {
        const auto line = given_lines.find(name);
        if (given.count(name) && line != given_lines.end() && line->second > 0) {
            location.line = line->second;
            break;
        }
    }
    throw ConfigError(location.file, location.line, fmt::format("{}: {}", technique.name(), conflict->message),
                      conflict->hint);
}

}  // namespace canopy
