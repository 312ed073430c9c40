// The timing cross-check (run/timing_check.hpp) on recorded samples: GPU passes that account for
// the frame agree; a pass read too short or too long is flagged; the tolerance is
// max(10 % of the wall time, 0.5 ms).
#include "run/timing_check.hpp"

#include <doctest/doctest.h>

using namespace canopy;

TEST_CASE("passes that add up to the wall time agree, within max(10 %, 0.5 ms)") {
    // Two passes of 3 and 5 ms, a wall time 0.3 ms longer (submission): agrees.
    const std::vector<std::vector<double>> passes{{3.0, 3.1, 2.9, 3.0}, {5.0, 5.2, 4.9, 5.0}};
    const TimingCheck ok = check_pass_timing(passes, {8.3, 8.6, 8.1, 8.3});
    CHECK(ok.checked);
    CHECK(ok.pass_sum_ms == doctest::Approx(8.0));
    CHECK(ok.gap_ms == doctest::Approx(0.3));
    CHECK(ok.tolerance_ms == doctest::Approx(0.83));
    CHECK(ok.agrees());
    // A pass read 20x too short (the lone-dispatch symptom): 5 ms reads 0.25 ms.
    const TimingCheck short_pass = check_pass_timing({{3.0, 3.0, 3.0}, {0.25, 0.25, 0.25}}, {8.3, 8.3, 8.3});
    CHECK(short_pass.gap_ms == doctest::Approx(5.05));
    CHECK_FALSE(short_pass.agrees());
    // Passes summing past the wall time cannot be: flagged too.
    CHECK_FALSE(check_pass_timing({{12.0, 12.0}}, {8.0, 8.0}).agrees());
    // Small frames: the 0.5 ms floor, not 10 % of 1 ms.
    CHECK(check_pass_timing({{1.0}}, {1.45}).agrees());
    CHECK_FALSE(check_pass_timing({{1.0}}, {1.55}).agrees());
}

TEST_CASE("the gap is the median of paired differences, not the difference of medians") {
    // Rounds where the wall time and the passes move together: the paired gap stays 0.2 ms even
    // though the medians of the two series come from different rounds.
    const std::vector<double> pass{1.0, 10.0, 2.0, 9.0, 3.0};
    std::vector<double> wall;
    for (double p : pass) wall.push_back(p + 0.2);
    const TimingCheck t = check_pass_timing({pass}, wall);
    CHECK(t.gap_ms == doctest::Approx(0.2));
}

TEST_CASE("nothing to check: no GPU pass or no sample") {
    CHECK_FALSE(check_pass_timing({}, {1.0}).checked);
    CHECK_FALSE(check_pass_timing({{}}, {}).checked);
    CHECK(check_pass_timing({}, {1.0}).agrees());
}
