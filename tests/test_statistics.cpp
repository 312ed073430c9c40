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
