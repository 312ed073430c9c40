#include "config/claim_rules.hpp"

#include <array>
#include <regex>
#include <stdexcept>

namespace canopy {

namespace {

// Fixed before any run was judged with them (issue 35). `about`: two rows the same, as the papers
// say "as fast as", "the same at 16 and 32 bits" — 15 %, canopy's reading since its first paper
// tables. Magnitude: a ratio reproduced on other hardware than the paper's — 25 %, the margin
// within which a researcher reads a table's ratio as reproduced.
constexpr std::array kToleranceRules{
    ToleranceRule{ToleranceUse::time_about, "time, about", 0.15,
                  "left/right's 95 % interval lies inside 1 ± t (outside: does not hold)"},
    ToleranceRule{ToleranceUse::time_magnitude, "time, magnitude", 0.25,
                  "canopy's ratio over the paper's (× k of the paper's): k's interval inside 1 ± t; judged on a GPU run only"},
    ToleranceRule{ToleranceUse::error_about, "error, about", 0.15, "|left − right| ≤ t × |right|"},
    ToleranceRule{ToleranceUse::error_magnitude, "error, magnitude", 0.25,
                  "left/right over the stated ratio within 1 ± t"},
};

constexpr std::array kDirectionReasons{
    DirectionReason{"no number", "the paper gives no number for it (it shows images, or says it in words)"},
    DirectionReason{"figure shape", "the paper's number is only a figure's shape"},
    DirectionReason{"canopy target", "the bound is canopy's own target (an issue's), not the paper's"},
};

}  // namespace

std::span<const ToleranceRule> tolerance_rules() { return kToleranceRules; }

double default_tolerance(ToleranceUse use) {
    for (const ToleranceRule& rule : kToleranceRules)
        if (rule.use == use) return rule.tolerance;
    throw std::logic_error("a tolerance use without a rule");
}

std::span<const DirectionReason> direction_reasons() { return kDirectionReasons; }

const DirectionReason* find_direction_reason(std::string_view key) {
    for (const DirectionReason& reason : kDirectionReasons)
        if (reason.key == key) return &reason;
    return nullptr;
}

std::optional<std::string> quoted_measurement(std::string_view text) {
    // A number followed by a unit of measure or a factor sign; "5x5" and "1024x768" are sizes
    // (a digit follows the x), "K23" and "L1040" have no unit after them.
    static const std::regex measurement(
        R"((×\s*\d+(?:[.,]\d+)?)|(\d+(?:[.,]\d+)?\s*(?:%|fps\b|ms\b|×|x(?![\dA-Za-z]))))");
    std::cmatch m;
    if (std::regex_search(text.data(), text.data() + text.size(), m, measurement)) return m.str();
    return std::nullopt;
}

std::optional<std::string> quoted_event_in_time(std::string_view text) {
    static const std::regex event(R"(\b(replac(?:e|es|ed|ing|ement|ements)|pop(?:s|ped|ping)?|flicker\w*|shimmer\w*|transitions?|temporal\w*)\b)",
                                  std::regex::icase);
    std::cmatch m;
    if (std::regex_search(text.data(), text.data() + text.size(), m, event)) return m.str();
    return std::nullopt;
}

}  // namespace canopy
