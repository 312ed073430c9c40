#include "core/technique.hpp"

#include "core/error.hpp"

#include <fmt/format.h>

namespace canopy {

const char* to_string(DepthFormat format) { return format == DepthFormat::d16 ? "d16" : "d32f"; }

const char* to_string(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return "r16f";
        case MomentFormat::r32f: return "r32f";
        case MomentFormat::rg16f: return "rg16f";
        case MomentFormat::rg32f: return "rg32f";
        case MomentFormat::rgba16f: return "rgba16f";
        case MomentFormat::rgba32f: return "rgba32f";
        case MomentFormat::rgba16unorm: return "rgba16unorm";
    }
    return "?";
}

uint32_t bytes_per_texel(MomentFormat format) {
    switch (format) {
        case MomentFormat::r16f: return 2;
        case MomentFormat::r32f: return 4;
        case MomentFormat::rg16f: return 4;
        case MomentFormat::rg32f: return 8;
        case MomentFormat::rgba16f: return 8;
        case MomentFormat::rgba32f: return 16;
        case MomentFormat::rgba16unorm: return 8;
    }
    return 0;
}

std::optional<ParamConflict> Technique::conflict(const ParamSet&) const { return std::nullopt; }

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
