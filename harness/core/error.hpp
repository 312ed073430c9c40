// Errors the user can fix (bad config, missing file, unsupported format) versus internal failures.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace canopy {

// A problem in the user's input. main() prints it as "file:line: error: message" plus a hint
// and exits with code 2.
class ConfigError : public std::runtime_error {
public:
    ConfigError(std::filesystem::path file, int line, std::string message, std::string hint = {})
        : std::runtime_error(std::move(message)), file_(std::move(file)), line_(line), hint_(std::move(hint)) {}

    const std::filesystem::path& file() const { return file_; }
    int line() const { return line_; }  // 0 when the problem has no line
    const std::string& hint() const { return hint_; }
    // "file:line: error: message\n  hint: ..." (parts omitted when absent)
    std::string formatted() const;

private:
    std::filesystem::path file_;
    int line_;
    std::string hint_;
};

// The Vulkan device or driver failed; not the user's input.
class GpuError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "Did you mean ...?" helper: the candidate closest to `word` by edit distance, or "" if none is close.
std::string closest_match(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace canopy
