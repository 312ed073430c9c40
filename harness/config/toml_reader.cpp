#include "config/toml_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

namespace canopy {

std::string read_config_file(const std::filesystem::path& file) {
    std::error_code status_error;
    const auto status = std::filesystem::status(file, status_error);
    if (!std::filesystem::exists(status))
        throw ConfigError(file, 0, "file not found",
                          fmt::format("check the path; relative paths are resolved against {}",
                                      std::filesystem::current_path().string()));
    if (std::filesystem::is_directory(status))
        throw ConfigError(file, 0, "is a folder, not a config file", "give the path of a .toml file");
    std::ifstream stream(file, std::ios::binary);
    if (!stream) throw ConfigError(file, 0, "cannot open the file", "check its permissions");
    std::string bytes{std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
    if (stream.bad()) throw ConfigError(file, 0, "cannot read the file", "check its permissions");
    return bytes;
}

toml::table parse_toml(const std::string& text, const std::filesystem::path& file) {
    try {
        return toml::parse(std::string_view(text), std::string(file.string()));
    } catch (const toml::parse_error& error) {
        throw ConfigError(file, int(error.source().begin.line),
                          fmt::format("malformed TOML: {}", error.description()),
                          "check the syntax on this line or just before it: strings need quotes, arrays "
                          "use [ ], each key = value goes on its own line (https://toml.io)");
    }
}

toml::table parse_toml_file(const std::filesystem::path& file) { return parse_toml(read_config_file(file), file); }

int line_of(const toml::node& node) { return int(node.source().begin.line); }

std::string describe_node(const toml::node& node) {
    switch (node.type()) {
        case toml::node_type::string: return fmt::format("the string \"{}\"", node.as_string()->get());
        case toml::node_type::integer: return fmt::format("the integer {}", node.as_integer()->get());
        case toml::node_type::floating_point: return fmt::format("the float {}", node.as_floating_point()->get());
        case toml::node_type::boolean: return fmt::format("the boolean {}", node.as_boolean()->get());
        case toml::node_type::array: return "an array";
        case toml::node_type::table: return "a table";
        case toml::node_type::date: return "a date";
        case toml::node_type::time: return "a time";
        case toml::node_type::date_time: return "a date-time";
        default: return "an unknown value";
    }
}

namespace {

// Shortest text for a float that reads back the same ("0.03", not "0.029999999329").
std::string format_number(float value) { return fmt::format("{}", value); }

std::string format_vector(const float* components, int count) {
    std::vector<std::string> parts;
    for (int i = 0; i < count; ++i) parts.push_back(format_number(components[i]));
    return fmt::format("[{}]", fmt::join(parts, ", "));
}

}  // namespace

TomlReader::TomlReader(const toml::table& table, std::filesystem::path file, std::string context)
    : table_(&table), file_(std::move(file)), context_(std::move(context)) {}

void TomlReader::mark_known(std::string_view key) {
    if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
}

const toml::node* TomlReader::find(std::string_view key) const { return table_->get(key); }

int TomlReader::line_of_key(std::string_view key) const {
    const auto entry = table_->find(key);
    if (entry == table_->end()) return line();
    const int key_line = int(entry->first.source().begin.line);
    return key_line > 0 ? key_line : line_of(entry->second);
}

bool TomlReader::has(std::string_view key) {
    mark_known(key);
    return find(key) != nullptr;
}

const toml::node* TomlReader::node(std::string_view key) {
    mark_known(key);
    const toml::node* found = find(key);
    if (found) read_.emplace(key);
    return found;
}

namespace {

std::string key_in_context(std::string_view key, const std::string& context) {
    return context.empty() ? fmt::format("'{}'", key) : fmt::format("'{}' in {}", key, context);
}

}  // namespace

std::string TomlReader::describe_key(std::string_view key) const { return key_in_context(key, context_); }

ConfigError TomlReader::error(std::string_view key, const std::string& message, const std::string& hint) const {
    return ConfigError(file_, line_of_key(key), message, hint);
}

ConfigError TomlReader::error_at(const toml::node& node, const std::string& message, const std::string& hint) const {
    const int node_line = line_of(node);
    return ConfigError(file_, node_line > 0 ? node_line : line(), message, hint);
}

ConfigError TomlReader::wrong_type(std::string_view key, const toml::node& node, const std::string& expected,
                                   const std::string& example) const {
    return error_at(node, fmt::format("{} must be {}, got {}", key_in_context(key, context_), expected, describe_node(node)),
                    fmt::format("write it as: {} = {}", key, example));
}

double TomlReader::number_from(std::string_view key, const toml::node& node, const std::string& expected,
                               const std::string& example) const {
    double value = 0.0;
    if (const auto* integer = node.as_integer()) value = double(integer->get());
    else if (const auto* real = node.as_floating_point()) value = real->get();
    else throw wrong_type(key, node, expected, example);
    if (!std::isfinite(value))
        throw error_at(node, fmt::format("{} must be a finite number, got {}", key_in_context(key, context_), value),
                       fmt::format("write it as: {} = {}", key, example));
    // Scenes are computed in single precision: 1e39 would silently become infinity.
    if (std::abs(value) > double(std::numeric_limits<float>::max()))
        throw error_at(node, fmt::format("{} = {} does not fit a single-precision float (at most {:.3g} in magnitude)",
                                         key_in_context(key, context_), value, std::numeric_limits<float>::max()),
                       fmt::format("write it as: {} = {}", key, example));
    return value;
}

double TomlReader::get_float(std::string_view key, double fallback) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    return number_from(key, *found, "a number", format_number(float(fallback)));
}

long long TomlReader::get_int(std::string_view key, long long fallback) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    if (const auto* integer = found->as_integer()) return integer->get();
    if (found->is_floating_point())
        throw error_at(*found, fmt::format("{} must be a whole number, got {}", key_in_context(key, context_),
                                           describe_node(*found)),
                       fmt::format("write it without a decimal point: {} = {}", key, fallback));
    throw wrong_type(key, *found, "an integer", std::to_string(fallback));
}

bool TomlReader::get_bool(std::string_view key, bool fallback) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    if (const auto* boolean = found->as_boolean()) return boolean->get();
    throw wrong_type(key, *found, "true or false (without quotes)", fallback ? "true" : "false");
}

std::string TomlReader::get_string(std::string_view key, const std::string& fallback) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    if (const auto* text = found->as_string()) return text->get();
    throw wrong_type(key, *found, "a string", fmt::format("\"{}\"", fallback.empty() ? "..." : fallback));
}

std::string TomlReader::require_string(std::string_view key, std::string_view example) {
    const toml::node* found = node(key);
    if (!found)
        throw ConfigError(file_, line(), fmt::format("{} needs '{}'", context_.empty() ? "the file" : context_, key),
                          fmt::format("add a line such as: {} = {}", key, example));
    if (const auto* text = found->as_string()) return text->get();
    throw wrong_type(key, *found, "a string", std::string(example));
}

glm::vec3 TomlReader::get_vec3(std::string_view key, const glm::vec3& fallback, Broadcast broadcast) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    const std::string example = format_vector(&fallback.x, 3);
    const std::string expected =
        broadcast == Broadcast::allowed ? "an array of 3 numbers or a single number" : "an array of 3 numbers";
    if (broadcast == Broadcast::allowed && (found->is_integer() || found->is_floating_point()))
        return glm::vec3(float(number_from(key, *found, expected, example)));
    const auto* array = found->as_array();
    if (!array || array->size() != 3) {
        if (array)
            throw error_at(*found, fmt::format("{} must be {}, got an array of {}", key_in_context(key, context_),
                                               expected, array->size()),
                           fmt::format("write it as: {} = {}", key, example));
        throw wrong_type(key, *found, expected, example);
    }
    glm::vec3 result;
    for (int i = 0; i < 3; ++i) result[i] = float(number_from(key, *array->get(size_t(i)), expected, example));
    return result;
}

glm::vec2 TomlReader::get_vec2(std::string_view key, const glm::vec2& fallback, Broadcast broadcast) {
    const toml::node* found = node(key);
    if (!found) return fallback;
    const std::string example = format_vector(&fallback.x, 2);
    const std::string expected =
        broadcast == Broadcast::allowed ? "an array of 2 numbers or a single number" : "an array of 2 numbers";
    if (broadcast == Broadcast::allowed && (found->is_integer() || found->is_floating_point()))
        return glm::vec2(float(number_from(key, *found, expected, example)));
    const auto* array = found->as_array();
    if (!array || array->size() != 2) {
        if (array)
            throw error_at(*found, fmt::format("{} must be {}, got an array of {}", key_in_context(key, context_),
                                               expected, array->size()),
                           fmt::format("write it as: {} = {}", key, example));
        throw wrong_type(key, *found, expected, example);
    }
    glm::vec2 result;
    for (int i = 0; i < 2; ++i) result[i] = float(number_from(key, *array->get(size_t(i)), expected, example));
    return result;
}

std::vector<std::string> TomlReader::get_string_array(std::string_view key) {
    const toml::node* found = node(key);
    if (!found) return {};
    const std::string example = "[\"first\", \"second\"]";
    const auto* array = found->as_array();
    if (!array) throw wrong_type(key, *found, "an array of strings", example);
    std::vector<std::string> strings;
    for (const toml::node& element : *array) {
        const auto* text = element.as_string();
        if (!text) throw wrong_type(key, element, "an array of strings", example);
        strings.push_back(text->get());
    }
    return strings;
}

std::optional<TomlReader> TomlReader::get_table(std::string_view key, std::string context) {
    const toml::node* found = node(key);
    if (!found) return std::nullopt;
    const auto* table = found->as_table();
    if (!table)
        throw error_at(*found, fmt::format("{} must be a table, got {}", key_in_context(key, context_),
                                           describe_node(*found)),
                       fmt::format("write it as a [{}] section with one key = value per line", key));
    return TomlReader(*table, file_, std::move(context));
}

std::vector<TomlReader> TomlReader::get_tables(std::string_view key, const std::string& context_prefix) {
    const toml::node* found = node(key);
    if (!found) return {};
    const auto* array = found->as_array();
    if (!array)
        throw error_at(*found, fmt::format("{} must be an array of tables, got {}", key_in_context(key, context_),
                                           describe_node(*found)),
                       found->is_table() ? fmt::format("write [[{}]] (double brackets) for each entry", key)
                                         : fmt::format("write a [[{}]] section for each entry", key));
    std::vector<TomlReader> readers;
    int index = 0;
    for (const toml::node& element : *array) {
        ++index;
        const auto* table = element.as_table();
        if (!table)
            throw error_at(element, fmt::format("entry {} of {} must be a table, got {}", index,
                                                key_in_context(key, context_), describe_node(element)),
                           fmt::format("write a [[{}]] section for each entry", key));
        readers.emplace_back(*table, file_, fmt::format("{} #{}", context_prefix, index));
    }
    return readers;
}

void TomlReader::reject(std::string_view key, const std::string& reason, const std::string& applies_to) {
    if (!has(key)) return;
    throw error(key, fmt::format("{} does not apply to {}", describe_key(key), reason), fmt::format("'{}' is used by {}; remove it here", key, applies_to));
}

void TomlReader::finish() const {
    const toml::key* first_unread = nullptr;
    const toml::node* first_unread_node = nullptr;
    for (auto&& [key, value] : *table_) {
        if (read_.count(key.str())) continue;
        const auto& position = key.source().begin;
        if (!first_unread || position.line < first_unread->source().begin.line ||
            (position.line == first_unread->source().begin.line &&
             position.column < first_unread->source().begin.column)) {
            first_unread = &key;
            first_unread_node = &value;
        }
    }
    if (!first_unread) return;

    const std::string name(first_unread->str());
    std::string what;
    if (first_unread_node->is_table()) what = fmt::format("unknown table [{}]", name);
    else if (first_unread_node->is_array_of_tables()) what = fmt::format("unknown table [[{}]]", name);
    else what = fmt::format("unknown key '{}'", name);
    if (!context_.empty()) what += fmt::format(" in {}", context_);

    std::string hint;
    const std::string suggestion = closest_match(name, known_);
    const std::string known_list = fmt::format("{}", fmt::join(known_, ", "));
    if (!suggestion.empty()) hint = fmt::format("did you mean '{}'? known keys: {}", suggestion, known_list);
    else if (!known_.empty()) hint = fmt::format("known keys: {}", known_list);

    int key_line = int(first_unread->source().begin.line);
    if (key_line == 0) key_line = line_of(*first_unread_node);
    throw ConfigError(file_, key_line, what, hint);
}

bool is_param_scalar(const toml::node& node) {
    return node.is_integer() || node.is_floating_point() || node.is_boolean() || node.is_string();
}

ParamValue to_param_value(const toml::node& node) {
    if (const auto* integer = node.as_integer()) return integer->get();
    if (const auto* real = node.as_floating_point()) return real->get();
    if (const auto* boolean = node.as_boolean()) return boolean->get();
    return node.as_string()->get();
}

}  // namespace canopy
