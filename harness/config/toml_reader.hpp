// A strict reader over one TOML table, shared by the scene and experiment loaders. Every getter
// checks the value's type and reports mistakes as ConfigError at the offending line, with a hint
// showing the expected form; finish() rejects every key that no getter asked for.
#pragma once

#include "core/error.hpp"
#include "core/param.hpp"
#include "scene/scene.hpp"

#include <toml++/toml.h>

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace canopy {

// The raw bytes of a config file. Throws ConfigError (no line) when it is missing or unreadable.
std::string read_config_file(const std::filesystem::path& file);

// Parses TOML text that came from `file`; malformed TOML becomes a ConfigError at its line.
toml::table parse_toml(const std::string& text, const std::filesystem::path& file);

// read_config_file + parse_toml.
toml::table parse_toml_file(const std::filesystem::path& file);

// The line a node starts on (0 when unknown).
int line_of(const toml::node& node);

// "the string \"abc\"", "the integer 3", "an array", ...: how a node reads in an error message.
std::string describe_node(const toml::node& node);

// Whether a vector getter also accepts one number, meaning that number in every component.
enum class Broadcast { allowed, forbidden };

// A TOML scalar (integer, float, bool, string) as a technique parameter value.
bool is_param_scalar(const toml::node& node);
ParamValue to_param_value(const toml::node& node);  // requires is_param_scalar(node)

class TomlReader {
public:
    // `context` names the table in messages: "[camera]", "[[light]] #2", "instance #1 of object 'floor'".
    TomlReader(const toml::table& table, std::filesystem::path file, std::string context);

    const toml::table& table() const { return *table_; }
    const std::filesystem::path& file() const { return file_; }
    const std::string& context() const { return context_; }
    int line() const { return line_of(*table_); }  // where the table starts
    SourceLocation where() const { return {file_, line()}; }
    int line_of_key(std::string_view key) const;  // the key's line, or the table's when absent
    std::string describe_key(std::string_view key) const;  // "'fov' in [camera]", for messages

    // Whether the key is present. Counts the key as known (for suggestions) but not as read.
    bool has(std::string_view key);
    // The node under `key`, marked as read, or nullptr when absent.
    const toml::node* node(std::string_view key);

    // Typed getters: the fallback when the key is absent, a ConfigError when it has the wrong type.
    double get_float(std::string_view key, double fallback);  // integers accepted; must be finite
    long long get_int(std::string_view key, long long fallback);  // a float is an error
    bool get_bool(std::string_view key, bool fallback);
    std::string get_string(std::string_view key, const std::string& fallback);
    glm::vec3 get_vec3(std::string_view key, const glm::vec3& fallback, Broadcast broadcast = Broadcast::allowed);
    glm::vec2 get_vec2(std::string_view key, const glm::vec2& fallback, Broadcast broadcast = Broadcast::allowed);
    std::vector<std::string> get_string_array(std::string_view key);  // empty when absent

    // Required variants: a ConfigError naming the key (and an example) when absent.
    std::string require_string(std::string_view key, std::string_view example);

    // Sub-tables. get_table accepts [key] or key = {...}; get_tables accepts [[key]] or
    // key = [{...}, ...]. Both return nothing when the key is absent.
    std::optional<TomlReader> get_table(std::string_view key, std::string context);
    std::vector<TomlReader> get_tables(std::string_view key, const std::string& context_prefix);

    // Throws when `key` is present: it exists in the schema, but not for this kind of table
    // (e.g. `radius` on a box). The hint says where it does apply.
    void reject(std::string_view key, const std::string& reason, const std::string& applies_to);

    // Errors located at a key's line (or the table's line when the key is absent) / at a node.
    ConfigError error(std::string_view key, const std::string& message, const std::string& hint = {}) const;
    ConfigError error_at(const toml::node& node, const std::string& message, const std::string& hint = {}) const;

    // Throws for the first key (in file order) that no getter read, suggesting the closest known key.
    void finish() const;

private:
    const toml::node* find(std::string_view key) const;
    ConfigError wrong_type(std::string_view key, const toml::node& node, const std::string& expected,
                           const std::string& example) const;
    double number_from(std::string_view key, const toml::node& node, const std::string& expected,
                       const std::string& example) const;

    const toml::table* table_;
    std::filesystem::path file_;
    std::string context_;
    std::vector<std::string> known_;           // every key a getter asked about, in asking order
    std::set<std::string, std::less<>> read_;  // keys that were present and consumed
    void mark_known(std::string_view key);
};

}  // namespace canopy
