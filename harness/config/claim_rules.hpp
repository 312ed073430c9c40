// The rules every [[paper.claim]] follows (issue 35), fixed before any run and written once:
// the tolerances a claim is judged with, the reasons a claim may check only a direction, and the
// words in a claim's text that commit it to a number or to something that happens in time.
// configs/README.md prints the same tables; tests/test_claim_rules.cpp fails when they drift.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace canopy {

// Which tolerance a claim part uses: `about` (the two rows the same: left/right within 1 ± t) or
// the magnitude (canopy's ratio over the paper's within 1 ± t), of a time or of an error metric.
enum class ToleranceUse { time_about, time_magnitude, error_about, error_magnitude };

struct ToleranceRule {
    ToleranceUse use;
    std::string_view key;    // "time, about"
    double tolerance;
    std::string_view why;    // words for the README's table
};
std::span<const ToleranceRule> tolerance_rules();
double default_tolerance(ToleranceUse use);

// The fixed list a `states = "direction"` claim takes its `why` from.
struct DirectionReason {
    std::string_view key;      // what the config writes: why = "no number"
    std::string_view meaning;  // what paper.md says
};
std::span<const DirectionReason> direction_reasons();
const DirectionReason* find_direction_reason(std::string_view key);

// A number the text quotes as a measurement: "545 %", "6.5x", "177 fps", "41.44 ms", "×10"
// ("11x11", "K23", "L1040", "16 bits" are names, not measurements). The first one, or nothing.
std::optional<std::string> quoted_measurement(std::string_view text);

// A word naming something that happens from frame to frame — replacement, popping, flicker,
// shimmer, a transition — which one still image cannot show. The first one, or nothing.
std::optional<std::string> quoted_event_in_time(std::string_view text);

}  // namespace canopy
