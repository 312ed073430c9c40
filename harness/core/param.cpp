#include "core/param.hpp"

#include "core/error.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

namespace canopy {

ParamSpec ParamSpec::integer(std::string name, long long def, long long min, long long max, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::integer;
    spec.default_value = def;
    spec.min = double(min);
    spec.max = double(max);
    spec.doc = std::move(doc);
    return spec;
}

ParamSpec ParamSpec::real(std::string name, double def, double min, double max, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::real;
    spec.default_value = def;
    spec.min = min;
    spec.max = max;
    spec.doc = std::move(doc);
    return spec;
}

ParamSpec ParamSpec::boolean(std::string name, bool def, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::boolean;
    spec.default_value = def;
    spec.doc = std::move(doc);
    return spec;
}

ParamSpec ParamSpec::choice(std::string name, std::string def, std::vector<std::string> choices, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::choice;
    spec.default_value = std::move(def);
    spec.choices = std::move(choices);
    spec.doc = std::move(doc);
    return spec;
}

ParamSpec ParamSpec::path(std::string name, std::string doc) {
    ParamSpec spec;
    spec.name = std::move(name);
    spec.type = ParamType::path;
    spec.default_value = std::string();
    spec.doc = std::move(doc);
    return spec;
}

namespace {

// Shortest text that reads back as the same double ("0.05", "1", "1e-06").
std::string format_real(double value) { return fmt::format("{}", value); }

// A declared number as its declaration wrote it: one declared from a float constant (0.15f) is
// the double nearest that float, 0.15000000596046448, shown as the float's shortest text, 0.15.
std::string format_declared(double value) {
    if (!(std::fabs(value) <= double(std::numeric_limits<float>::max()))) return format_real(value);  // no float holds it
    const float narrow = float(value);
    return double(narrow) == value ? fmt::format("{}", narrow) : format_real(value);
}

std::string range_text(const ParamSpec& spec) {
    if (spec.type == ParamType::integer)
        return fmt::format("[{}, {}]", (long long)spec.min, (long long)spec.max);
    return fmt::format("[{}, {}]", format_declared(spec.min), format_declared(spec.max));
}

// How a given value reads in a message: "the string 'abc'", "the real number 2.5".
std::string describe(const ParamValue& value) {
    struct Describe {
        std::string operator()(long long v) const { return fmt::format("the integer {}", v); }
        std::string operator()(double v) const { return fmt::format("the real number {}", format_real(v)); }
        std::string operator()(bool v) const { return fmt::format("the boolean {}", v); }
        std::string operator()(const std::string& v) const { return fmt::format("the string '{}'", v); }
    };
    return std::visit(Describe{}, value);
}

// An example of a well-formed value for the spec, used in hints: kernel = 5, pattern = "grid".
std::string example_assignment(const ParamSpec& spec) {
    if (spec.type == ParamType::choice)
        return fmt::format("{} = \"{}\"", spec.name, to_string(spec.default_value));
    if (spec.type == ParamType::path) return fmt::format("{} = \"maps/{}.png\"", spec.name, spec.name);
    return fmt::format("{} = {}", spec.name, to_string(spec.default_value));
}

std::string join(const std::vector<std::string>& words, const char* separator) {
    return fmt::format("{}", fmt::join(words, separator));
}

bool holds_declared_type(const ParamSpec& spec, const ParamValue& value) {
    switch (spec.type) {
        case ParamType::integer: return std::holds_alternative<long long>(value);
        case ParamType::real: return std::holds_alternative<double>(value);
        case ParamType::boolean: return std::holds_alternative<bool>(value);
        case ParamType::choice:
        case ParamType::path: return std::holds_alternative<std::string>(value);
    }
    return false;
}

// Checks one user-given value against its spec and returns it in the spec's own type.
class ValueChecker {
public:
    ValueChecker(const ParamSpec& spec, const SourceLocation& where, const std::string& technique)
        : spec_(spec), where_(where), technique_(technique) {}

    ParamValue check(const ParamValue& given) const {
        switch (spec_.type) {
            case ParamType::integer: return check_integer(given);
            case ParamType::real: return check_real(given);
            case ParamType::boolean: return check_boolean(given);
            case ParamType::choice: return check_choice(given);
            case ParamType::path: return check_path(given);
        }
        throw std::logic_error("unhandled ParamType");
    }

private:
    ConfigError error(const std::string& message, const std::string& hint) const {
        return ConfigError(where_.file, where_.line, fmt::format("{}: {}", technique_, message), hint);
    }

    ConfigError wrong_type(const ParamValue& given, const char* expected) const {
        return error(fmt::format("parameter '{}' must be {} ({}), got {}", spec_.name, expected,
                                 spec_.type_and_range(), describe(given)),
                     fmt::format("for example: {}", example_assignment(spec_)));
    }

    void check_range(double value, const std::string& shown) const {
        if (value >= spec_.min && value <= spec_.max) return;  // also rejects NaN
        throw error(fmt::format("value {} is out of range for '{}' ({})", shown, spec_.name, spec_.type_and_range()),
                    fmt::format("use a value in {}", range_text(spec_)));
    }

    ParamValue check_integer(const ParamValue& given) const {
        if (const double* real = std::get_if<double>(&given)) {
            // Accepting 5.0 would hide a misunderstanding of what the parameter counts.
            throw error(fmt::format("parameter '{}' must be an integer ({}), got the real number {}", spec_.name,
                                    spec_.type_and_range(), format_real(*real)),
                        fmt::format("write a whole number without a decimal point, for example: {}",
                                    example_assignment(spec_)));
        }
        const long long* integer = std::get_if<long long>(&given);
        if (!integer) throw wrong_type(given, "an integer");
        check_range(double(*integer), std::to_string(*integer));
        return *integer;
    }

    ParamValue check_real(const ParamValue& given) const {
        double value = 0.0;
        if (const long long* integer = std::get_if<long long>(&given)) value = double(*integer);
        else if (const double* real = std::get_if<double>(&given)) value = *real;
        else throw wrong_type(given, "a number");
        check_range(value, to_string(given));
        return value;
    }

    ParamValue check_boolean(const ParamValue& given) const {
        if (!std::holds_alternative<bool>(given)) {
            throw error(fmt::format("parameter '{}' must be a boolean (true or false), got {}", spec_.name,
                                    describe(given)),
                        fmt::format("write true or false without quotes, for example: {}",
                                    example_assignment(spec_)));
        }
        return given;
    }

    ParamValue check_choice(const ParamValue& given) const {
        const std::string* text = std::get_if<std::string>(&given);
        if (!text) {
            throw error(fmt::format("parameter '{}' must be a string, {}, got {}", spec_.name,
                                    spec_.type_and_range(), describe(given)),
                        fmt::format("write the choice in quotes, for example: {}", example_assignment(spec_)));
        }
        if (std::find(spec_.choices.begin(), spec_.choices.end(), *text) != spec_.choices.end()) return given;
        const std::string suggestion = closest_match(*text, spec_.choices);
        const std::string allowed = join(spec_.choices, ", ");
        throw error(fmt::format("value '{}' is not allowed for '{}' ({})", *text, spec_.name, spec_.type_and_range()),
                    suggestion.empty() ? fmt::format("use one of: {}", allowed)
                                       : fmt::format("did you mean '{}'? allowed values: {}", suggestion, allowed));
    }

    // A relative path is taken from the folder of the file that gives it; the file must exist.
    ParamValue check_path(const ParamValue& given) const {
        const std::string* text = std::get_if<std::string>(&given);
        if (!text)
            throw error(fmt::format("parameter '{}' must be a file path in quotes, got {}", spec_.name, describe(given)),
                        fmt::format("for example: {}", example_assignment(spec_)));
        if (text->empty()) return given;
        std::filesystem::path file(*text);
        if (file.is_relative() && !where_.file.empty()) file = where_.file.parent_path() / file;
        file = std::filesystem::absolute(file).lexically_normal();
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
            throw error(fmt::format("parameter '{}' names '{}', which is not a file (looked for {})", spec_.name, *text,
                                    file.string()),
                        where_.file.empty() ? "give the file's path"
                                            : fmt::format("a relative path is taken from the folder of {}",
                                                          where_.file.filename().string()));
        return file.string();
    }

    const ParamSpec& spec_;
    const SourceLocation& where_;
    const std::string& technique_;
};

}  // namespace

std::string ParamSpec::type_and_range() const {
    switch (type) {
        case ParamType::integer: return fmt::format("int in {}", range_text(*this));
        case ParamType::real: return fmt::format("float in {}", range_text(*this));
        case ParamType::boolean: return "bool";
        case ParamType::choice: return fmt::format("one of {}", join(choices, "|"));
        case ParamType::path: return "file path";
    }
    return "?";
}

std::string to_string(const ParamValue& value) {
    struct Format {
        std::string operator()(long long v) const { return std::to_string(v); }
        std::string operator()(double v) const { return format_real(v); }
        std::string operator()(bool v) const { return v ? "true" : "false"; }
        std::string operator()(const std::string& v) const { return v; }
    };
    return std::visit(Format{}, value);
}

std::string default_text(const ParamSpec& spec) {
    if (spec.type == ParamType::path && to_string(spec.default_value).empty()) return "none";
    if (const double* real = std::get_if<double>(&spec.default_value)) return format_declared(*real);
    return to_string(spec.default_value);
}

ParamSet ParamSet::resolve(const std::vector<ParamSpec>& specs, const std::map<std::string, ParamValue>& given,
                           const std::map<std::string, int>& given_lines, const SourceLocation& where,
                           const std::string& technique) {
    std::vector<std::string> names;
    for (const ParamSpec& spec : specs) names.push_back(spec.name);

    auto location_of = [&](const std::string& name) {
        SourceLocation location = where;
        if (auto line = given_lines.find(name); line != given_lines.end() && line->second > 0)
            location.line = line->second;
        return location;
    };

    for (const auto& [name, value] : given) {
        if (std::find(names.begin(), names.end(), name) != names.end()) continue;
        const SourceLocation location = location_of(name);
        std::string hint;
        if (names.empty()) {
            hint = fmt::format("{} takes no parameters; remove [technique.params]", technique);
        } else {
            const std::string suggestion = closest_match(name, names);
            const std::string known = fmt::format("parameters of {}: {}", technique, join(names, ", "));
            hint = suggestion.empty() ? known : fmt::format("did you mean '{}'? {}", suggestion, known);
        }
        throw ConfigError(location.file, location.line,
                          fmt::format("{}: parameter '{}' is unknown", technique, name), hint);
    }

    ParamSet set;
    for (const ParamSpec& spec : specs) {
        if (!holds_declared_type(spec, spec.default_value))
            throw std::logic_error(fmt::format("{}: default of parameter '{}' does not have its declared type",
                                               technique, spec.name));
        const auto given_value = given.find(spec.name);
        if (given_value == given.end()) {
            set.values_.emplace_back(spec.name, spec.default_value);
            continue;
        }
        const SourceLocation location = location_of(spec.name);
        set.values_.emplace_back(spec.name, ValueChecker(spec, location, technique).check(given_value->second));
    }
    return set;
}

const ParamValue& ParamSet::at(const std::string& name) const {
    for (const auto& [key, value] : values_)
        if (key == name) return value;
    throw std::logic_error(fmt::format("ParamSet has no parameter '{}'", name));
}

namespace {

template <typename T>
const T& get_typed(const ParamValue& value, const std::string& name, const char* type) {
    if (const T* typed = std::get_if<T>(&value)) return *typed;
    throw std::logic_error(fmt::format("parameter '{}' is not of type {}", name, type));
}

}  // namespace

long long ParamSet::integer(const std::string& name) const { return get_typed<long long>(at(name), name, "integer"); }
double ParamSet::real(const std::string& name) const { return get_typed<double>(at(name), name, "real"); }
bool ParamSet::boolean(const std::string& name) const { return get_typed<bool>(at(name), name, "boolean"); }
const std::string& ParamSet::choice(const std::string& name) const {
    return get_typed<std::string>(at(name), name, "choice");
}
const std::string& ParamSet::path(const std::string& name) const { return get_typed<std::string>(at(name), name, "path"); }

std::string ParamSet::summary() const {
    std::vector<std::string> parts;
    for (const auto& [name, value] : values_) parts.push_back(fmt::format("{}={}", name, to_string(value)));
    return join(parts, " ");
}

}  // namespace canopy
