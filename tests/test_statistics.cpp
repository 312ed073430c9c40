#include "run/statistics.hpp"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;

TEST_CASE("statistics of an odd number of samples") {
    const SampleStats s = summarize({5.0, 1.0, 3.0, 2.0, 100.0});
    CHECK(s.count == 5);
    CHECK(s.median == 3.0);
    CHECK(s.min == 1.0);
    CHECK(s.max == 100.0);
    CHECK(s.mean == doctest::Approx(22.2));
    CHECK(s.mad == 2.0);  // deviations 2, 2, 0, 1, 97 -> median 2
    // sample standard deviation of {1,2,3,5,100} = sqrt(7575.8 / 4) = 43.5167
    CHECK(s.cv == doctest::Approx(43.5167 / 22.2).epsilon(1e-4));
}

TEST_CASE("statistics of an even number of samples take the mean of the middle two") {
    const SampleStats s = summarize({4.0, 1.0, 3.0, 2.0});
    CHECK(s.median == 2.5);
    CHECK(s.mad == 1.0);  // deviations 1.5, 0.5, 0.5, 1.5
}

TEST_CASE("constant samples have zero spread") {
    const SampleStats s = summarize({7.0, 7.0, 7.0});
    CHECK(s.median == 7.0);
    CHECK(s.mad == 0.0);
    CHECK(s.cv == 0.0);
}

TEST_CASE("a single sample and no samples") {
    const SampleStats one = summarize({2.5});
    CHECK(one.median == 2.5);
    CHECK(one.cv == 0.0);
    const SampleStats none = summarize({});
    CHECK(none.count == 0);
    CHECK(none.median == 0.0);
}

#include "run/kernel_scaling.hpp"

TEST_CASE("power-law fit recovers the exponent despite a constant offset") {
    const std::vector<double> widths{3, 7, 11, 15, 21, 31};
    for (double exponent : {1.0, 2.0, 1.5}) {
        std::vector<double> times;
        for (double w : widths) times.push_back(4.0 + 0.25 * std::pow(w, exponent));
        const PowerFit fit = fit_power_law(widths, times);
        CAPTURE(exponent);
        CHECK(fit.exponent == doctest::Approx(exponent).epsilon(0.01));
        CHECK(fit.offset == doctest::Approx(4.0).epsilon(0.05));
        CHECK(fit.r_squared > 0.9999);
    }
}

TEST_CASE("power-law fit of noisy linear data stays near 1") {
    const std::vector<double> widths{3, 7, 11, 15, 21, 31};
    const std::vector<double> noise{0.02, -0.03, 0.01, 0.03, -0.02, 0.01};
    std::vector<double> times;
    for (size_t i = 0; i < widths.size(); ++i) times.push_back(2.0 + 0.1 * widths[i] * (1.0 + noise[i]));
    const PowerFit fit = fit_power_law(widths, times);
    CHECK(fit.exponent > 0.8);
    CHECK(fit.exponent < 1.25);
}

TEST_CASE("power-law fit keeps the offset non-negative on concave data") {
    // Sub-linear growth through the origin: an unconstrained fit would invent a negative offset.
    const std::vector<double> widths{5, 9, 13, 17, 23, 31};
    std::vector<double> times;
    for (double w : widths) times.push_back(20.0 * std::pow(w, 0.7));
    const PowerFit fit = fit_power_law(widths, times);
    CHECK(fit.offset >= 0.0);
    CHECK(fit.exponent == doctest::Approx(0.7).epsilon(0.02));
}

TEST_CASE("quantile_of_sorted interpolates between order statistics (numpy's default)") {
    const std::vector<double> v{1.0, 2.0, 3.0, 4.0};
    CHECK(quantile_of_sorted(v, 0.0) == 1.0);
    CHECK(quantile_of_sorted(v, 1.0) == 4.0);
    CHECK(quantile_of_sorted(v, 0.5) == doctest::Approx(2.5));
    CHECK(quantile_of_sorted(v, 0.05) == doctest::Approx(1.15));  // numpy.quantile([1, 2, 3, 4], 0.05)
    CHECK(quantile_of_sorted(v, 0.95) == doctest::Approx(3.85));
    CHECK(quantile_of_sorted({7.0}, 0.3) == 7.0);
    CHECK(std::isnan(quantile_of_sorted({}, 0.5)));
}
