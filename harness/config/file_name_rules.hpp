// Which names may become parts of file names: scene and experiment names end up in case ids,
// image names and output folders, so they must not escape a folder ("../../x"), hide a file
// (".x"), or carry characters that shells, terminals or other file systems trip over. Names
// in any script stay readable: non-ASCII letters are kept as they are (UTF-8).
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace canopy {

// The longest name, in bytes of UTF-8: a case id adds the resolution, technique and parameters,
// and file names are limited to 255 bytes.
inline constexpr size_t kMaxNameBytes = 100;

// What the rule allows, for hints: "letters of any script, digits, '.', '_' and '-'; ...".
extern const char* const kFileNameRule;

// Why `name` cannot be used as (part of) a file name, or nothing when it can.
std::optional<std::string> file_name_problem(std::string_view name);

// `text` with every character the rule does not allow (and every invalid UTF-8 byte) replaced
// by '-'. Leading dots and ".." are not rewritten: give it names file_name_problem accepted.
std::string file_name_safe(std::string_view text);

// `name` quoted for an error message, with control characters and invalid UTF-8 escaped
// (\x1b, ...) so that printing it cannot garble the terminal.
std::string printable_name(std::string_view name);

}  // namespace canopy
