#include "config/file_name_rules.hpp"

#include <fmt/format.h>

namespace canopy {

const char* const kFileNameRule =
    "letters of any script, digits, '.', '_' and '-' (no spaces, no '/', not starting with '.' or '-', no '..')";

namespace {

constexpr char32_t kInvalid = 0xFFFFFFFF;

// Decodes the UTF-8 sequence at `text[at]`, advancing `at`; kInvalid for a malformed,
// overlong, surrogate or out-of-range sequence (then `at` advances by one byte).
char32_t next_code_point(std::string_view text, size_t& at) {
    const auto byte = [&](size_t i) { return static_cast<unsigned char>(text[i]); };
    const unsigned char first = byte(at);
    if (first < 0x80) {
        ++at;
        return first;
    }
    size_t length = 0;
    char32_t code = 0, minimum = 0;
    if ((first & 0xE0) == 0xC0) length = 2, code = first & 0x1F, minimum = 0x80;
    else if ((first & 0xF0) == 0xE0) length = 3, code = first & 0x0F, minimum = 0x800;
    else if ((first & 0xF8) == 0xF0) length = 4, code = first & 0x07, minimum = 0x10000;
    if (length == 0 || at + length > text.size()) {
        ++at;
        return kInvalid;
    }
    for (size_t i = 1; i < length; ++i) {
        if ((byte(at + i) & 0xC0) != 0x80) {
            ++at;
            return kInvalid;
        }
        code = (code << 6) | (byte(at + i) & 0x3F);
    }
    if (code < minimum || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) {
        ++at;
        return kInvalid;
    }
    at += length;
    return code;
}

bool is_ascii_name_character(char32_t c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '.' || c == '_' ||
           c == '-';
}

// Non-ASCII characters that read as nothing or as something else: C1 controls, spaces,
// invisible formatting and direction marks, private-use and non-characters, and the look-alikes
// of '/' and '\'.
bool is_unreadable(char32_t c) {
    return c < 0xA0 || c == 0xA0 || c == 0xAD || c == 0x034F || c == 0x061C || c == 0x1680 || c == 0x180E ||
           (c >= 0x2000 && c <= 0x200F) || (c >= 0x2028 && c <= 0x202F) || (c >= 0x205F && c <= 0x206F) ||
           c == 0x3000 || c == 0x3164 || c == 0xFEFF || c == 0xFFA0 || (c >= 0xFFF0 && c <= 0xFFFF) ||
           (c >= 0xFDD0 && c <= 0xFDEF) || (c & 0xFFFE) == 0xFFFE || (c >= 0xE000 && c <= 0xF8FF) ||
           c >= 0xF0000 || (c >= 0xFE00 && c <= 0xFE0F) || (c >= 0xE0000 && c <= 0xE0FFF) || c == 0x2044 ||
           c == 0x2215 || c == 0x29F8 || c == 0x29F9 || c == 0xFF0F || c == 0xFF3C;
}

bool is_name_character(char32_t c) { return c < 0x80 ? is_ascii_name_character(c) : !is_unreadable(c); }

std::string describe(char32_t c) {
    if (c == ' ') return "a space";
    if (c == '/' || c == '\\') return fmt::format("'{}', a path separator", char(c));
    if (c < 0x20 || c == 0x7F) return fmt::format("the control character U+{:04X}", uint32_t(c));
    if (c < 0x80) return fmt::format("'{}'", char(c));
    return fmt::format("the character U+{:04X}, which is invisible, a space or a look-alike of '/'", uint32_t(c));
}

}  // namespace

std::optional<std::string> file_name_problem(std::string_view name) {
    if (name.empty()) return std::string("it is empty");
    if (name.size() > kMaxNameBytes)
        return fmt::format("it is {} bytes long; at most {} are allowed", name.size(), kMaxNameBytes);
    if (name.find("..") != std::string_view::npos) return std::string("it contains '..', which leads out of a folder");
    for (size_t at = 0; at < name.size();) {
        const char32_t c = next_code_point(name, at);
        if (c == kInvalid) return std::string("it is not valid UTF-8");
        if (!is_name_character(c)) return fmt::format("it contains {}", describe(c));
    }
    if (name.front() == '.') return std::string("it starts with '.', which hides files named after it");
    if (name.front() == '-') return std::string("it starts with '-', which shell tools read as an option");
    return std::nullopt;
}

std::string file_name_safe(std::string_view text) {
    std::string safe;
    safe.reserve(text.size());
    for (size_t at = 0; at < text.size();) {
        const size_t start = at;
        const char32_t c = next_code_point(text, at);
        if (c != kInvalid && is_name_character(c)) safe.append(text.substr(start, at - start));
        else safe.push_back('-');
    }
    return safe;
}

std::string printable_name(std::string_view name) {
    constexpr size_t kShown = 120;  // bytes of a long name worth showing
    std::string quoted = "'";
    for (size_t at = 0; at < name.size();) {
        if (quoted.size() > kShown) {
            quoted += "...";
            break;
        }
        const size_t start = at;
        const char32_t c = next_code_point(name, at);
        if (c == kInvalid || c < 0x20 || c == 0x7F || (c >= 0x80 && c < 0xA0)) {
            for (size_t i = start; i < at; ++i) quoted += fmt::format("\\x{:02x}", static_cast<unsigned char>(name[i]));
        } else {
            quoted.append(name.substr(start, at - start));
        }
    }
    return quoted + "'";
}

}  // namespace canopy
