#include "core/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <limits>
#include <numeric>

namespace canopy {

std::string ConfigError::formatted() const {
    std::string location;
    if (!file_.empty()) location = file_.string();
    if (line_ > 0) location += location.empty() ? fmt::format("line {}", line_) : fmt::format(":{}", line_);
    std::string text = location.empty() ? fmt::format("error: {}", what())
                                         : fmt::format("{}: error: {}", location, what());
    if (!hint_.empty()) text += fmt::format("\n  hint: {}", hint_);
    return text;
}

namespace {

std::string lowercase(const std::string& text) {
    std::string lower = text;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return lower;
}

// Classic two-row Levenshtein distance: insertions, deletions and substitutions cost 1.
size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
    std::iota(previous.begin(), previous.end(), size_t{0});
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            const size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

}  // namespace

std::string closest_match(const std::string& word, const std::vector<std::string>& candidates) {
    const std::string needle = lowercase(word);
    std::string best;
    size_t best_distance = std::numeric_limits<size_t>::max();
    for (const std::string& candidate : candidates) {
        const size_t distance = edit_distance(needle, lowercase(candidate));
        if (distance < best_distance) {
            best_distance = distance;
            best = candidate;
        }
    }
    // Beyond this the "suggestion" would be a different word, which misleads more than it helps.
    const size_t tolerance = std::max<size_t>(2, word.size() / 3);
    return best_distance <= tolerance ? best : std::string{};
}

}  // namespace canopy
