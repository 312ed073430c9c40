// Typed, documented technique parameters (the pbrt/Mitsuba plug-in style): each technique
// declares ParamSpecs; configs give ParamValues; validation checks type and range.
#pragma once

#include "scene/object.hpp"

#include <map>
#include <string>
#include <variant>
#include <vector>

namespace canopy {

// path: a file; a relative one given in a config is taken from the folder of the file that gives it,
// and must exist ("" names none).
enum class ParamType { integer, real, boolean, choice, path };

using ParamValue = std::variant<long long, double, bool, std::string>;

struct ParamSpec {
    std::string name;
    ParamType type = ParamType::real;
    ParamValue default_value;
    double min = 0.0, max = 0.0;         // integer and real: inclusive range
    std::vector<std::string> choices;    // choice: allowed strings
    std::string doc;                     // one line

    static ParamSpec integer(std::string name, long long def, long long min, long long max, std::string doc);
    static ParamSpec real(std::string name, double def, double min, double max, std::string doc);
    static ParamSpec boolean(std::string name, bool def, std::string doc);
    static ParamSpec choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc);
    static ParamSpec path(std::string name, std::string doc);  // default "": none

    // "int in [1, 31]", "float in [0, 0.05]", "bool", "one of grid|poisson", "file path"
    std::string type_and_range() const;
};

std::string to_string(const ParamValue& value);
// A spec's default as `canopy list` shows it: to_string, or "none" for a path naming no file.
std::string default_text(const ParamSpec& spec);

// Concrete values for every declared parameter of one technique, defaults filled in.
class ParamSet {
public:
    ParamSet() = default;

    // Defaults for every spec, then `given` applied. Throws ConfigError at `where` (with the
    // parameter's own line when known) for unknown names, wrong types, out-of-range values.
    // An integer given where a real is expected is accepted.
    static ParamSet resolve(const std::vector<ParamSpec>& specs,
                            const std::map<std::string, ParamValue>& given,
                            const std::map<std::string, int>& given_lines,
                            const SourceLocation& where, const std::string& technique);

    long long integer(const std::string& name) const;
    double real(const std::string& name) const;
    bool boolean(const std::string& name) const;
    const std::string& choice(const std::string& name) const;
    const std::string& path(const std::string& name) const;  // as resolved: absolute, or "" for none

    // In declaration order, for reports.
    const std::vector<std::pair<std::string, ParamValue>>& values() const { return values_; }
    // "kernel=5 pattern=poisson ...": every value, in declaration order.
    std::string summary() const;

private:
    const ParamValue& at(const std::string& name) const;
    std::vector<std::pair<std::string, ParamValue>> values_;
};

}  // namespace canopy
