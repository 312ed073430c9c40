// The block bootstrap behind every timing interval (run/block_bootstrap.hpp) and the order of the
// cases within a round (run/round_order.hpp).
#include "run/block_bootstrap.hpp"
#include "run/round_order.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <set>

using namespace canopy;

namespace {

// Normal-ish noise from a fixed generator: sum of 12 uniforms - 6.
std::vector<double> noisy(size_t n, double centre, double spread, uint64_t seed) {
    SplitMix64 random(seed);
    std::vector<double> v;
    for (size_t i = 0; i < n; ++i) {
        double z = -6.0;
        for (int k = 0; k < 12; ++k) z += double(random.next() >> 11) * 0x1.0p-53;
        v.push_back(centre * (1.0 + spread * z));
    }
    return v;
}

}  // namespace

TEST_CASE("block length grows as the cube root of the rounds") {
    CHECK(default_block_length(0) == 1);
    CHECK(default_block_length(1) == 1);
    CHECK(default_block_length(3) == 2);
    CHECK(default_block_length(8) == 2);
    CHECK(default_block_length(9) == 3);
    CHECK(default_block_length(27) == 3);
    CHECK(default_block_length(30) == 4);
    CHECK(default_block_length(1000) == 10);
}

TEST_CASE("a circular block resample keeps runs of consecutive rounds") {
    std::vector<double> values;
    for (int i = 0; i < 20; ++i) values.push_back(i);
    SplitMix64 random(7);
    std::vector<double> out;
    resample_blocks(values, 4, random, out);
    REQUIRE(out.size() == values.size());
    // Every block of 4 is 4 consecutive values modulo 20.
    for (size_t b = 0; b < out.size(); b += 4)
        for (size_t j = 1; j < 4 && b + j < out.size(); ++j) CHECK(out[b + j] == std::fmod(out[b + j - 1] + 1.0, 20.0));
}

TEST_CASE("the median's interval covers the median, is reproducible, and narrows with more rounds") {
    const std::vector<double> few = noisy(10, 2.0, 0.05, 1);
    const std::vector<double> many = noisy(200, 2.0, 0.05, 1);
    const Estimate a = median_with_ci(few, 42), b = median_with_ci(few, 42);
    CHECK(a.value == b.value);
    CHECK(a.ci.low == b.ci.low);
    CHECK(a.ci.high == b.ci.high);
    CHECK(a.ci.low <= a.value);
    CHECK(a.value <= a.ci.high);
    CHECK(a.count == 10);
    const Estimate wide = median_with_ci(many, 42);
    CHECK(wide.ci.high - wide.ci.low < a.ci.high - a.ci.low);
    CHECK(wide.value == doctest::Approx(2.0).epsilon(0.01));
}

TEST_CASE("constant, single and empty series") {
    const Estimate constant = median_with_ci({1.5, 1.5, 1.5, 1.5}, 1);
    CHECK(constant.value == 1.5);
    CHECK(constant.ci.low == 1.5);
    CHECK(constant.ci.high == 1.5);
    const Estimate one = median_with_ci({3.0}, 1);
    CHECK(one.ci.low == 3.0);
    CHECK(one.ci.high == 3.0);
    const Estimate none = median_with_ci({}, 1);
    CHECK(none.count == 0);
    CHECK(std::isnan(none.value));
}

TEST_CASE("median_of takes the middle value or the mean of the middle two") {
    CHECK(median_of({3.0, 1.0, 2.0}) == 2.0);
    CHECK(median_of({4.0, 1.0, 3.0, 2.0}) == 2.5);
    CHECK(std::isnan(median_of({})));
}

namespace {

// How often the interval of 30 rounds covers the true median 1.0, over 400 series whose noise is
// an AR(1) level with coefficient `phi` (0: independent rounds).
double coverage(double phi) {
    int covered = 0;
    const int trials = 400;
    for (int t = 0; t < trials; ++t) {
        SplitMix64 random(1000 + uint64_t(t));
        std::vector<double> v;
        double level = 0.0;
        for (int i = 0; i < 30; ++i) {
            const double shock = double(random.next() >> 11) * 0x1.0p-53 - 0.5;
            level = phi * level + shock;
            v.push_back(1.0 + 0.05 * level);
        }
        const Estimate e = median_with_ci(v, uint64_t(t));
        covered += e.ci.low <= 1.0 && 1.0 <= e.ci.high ? 1 : 0;
    }
    return double(covered) / trials;
}

}  // namespace

TEST_CASE("the 95 % interval of a median covers the true median nearly 95 % of the time") {
    // The block bootstrap is approximate: with 30 rounds it covers about 92 % for independent
    // rounds and about 80 % when load shifts carry over (AR(1), 0.6) — the README says so.
    CHECK(coverage(0.0) >= 0.88);
    CHECK(coverage(0.6) >= 0.74);
}

TEST_CASE("relative change and ratio of medians of independent series") {
    const std::vector<double> base = noisy(30, 2.0, 0.02, 3);
    const std::vector<double> slower = noisy(30, 2.4, 0.02, 4);  // 20 % more
    const Estimate change = relative_change_with_ci(base, slower, 9);
    CHECK(change.value == doctest::Approx(0.2).epsilon(0.05));
    CHECK(change.ci.low > 0.15);
    CHECK(change.ci.high < 0.25);
    const Estimate ratio = ratio_of_medians_with_ci(slower, base, 9);
    CHECK(ratio.value == doctest::Approx(1.2).epsilon(0.02));
    CHECK(ratio.ci.low > 1.1);
    const Estimate same = relative_change_with_ci(base, noisy(30, 2.0, 0.02, 5), 9);
    CHECK(same.ci.low < 0.0);
    CHECK(same.ci.high > 0.0);
}

TEST_CASE("the seed of a series depends on its label only") {
    CHECK(bootstrap_seed("a") == bootstrap_seed("a"));
    CHECK(bootstrap_seed("a") != bootstrap_seed("b"));
    SplitMix64 random(5);
    for (int i = 0; i < 1000; ++i) CHECK(random.below(7) < 7);
}

TEST_CASE("round orders are permutations that balance position and predecessor") {
    for (size_t n : {1u, 2u, 3u, 4u, 5u, 6u, 7u, 16u}) {
        CAPTURE(n);
        const size_t cycle = williams_cycle(n);
        CHECK(cycle == (n <= 1 ? 1 : n % 2 == 0 ? n : 2 * n));
        std::vector<std::vector<int>> at_position(n, std::vector<int>(n, 0));
        std::vector<std::vector<int>> follows(n, std::vector<int>(n, 0));
        for (size_t r = 0; r < cycle; ++r) {
            const std::vector<size_t> order = round_order(n, r);
            REQUIRE(order.size() == n);
            CHECK(std::set<size_t>(order.begin(), order.end()).size() == n);
            for (size_t k = 0; k < n; ++k) {
                ++at_position[order[k]][k];
                if (k > 0) ++follows[order[k - 1]][order[k]];
            }
        }
        // Every case at every position equally often; every ordered pair adjacent equally often.
        const int per_position = int(cycle / n);
        for (size_t c = 0; c < n; ++c)
            for (size_t k = 0; k < n; ++k) CHECK(at_position[c][k] == per_position);
        if (n > 1) {
            const int per_pair = int(cycle * (n - 1) / (n * (n - 1)));
            for (size_t a = 0; a < n; ++a)
                for (size_t b = 0; b < n; ++b)
                    if (a != b) CHECK(follows[a][b] == per_pair);
        }
        CHECK(round_order(n, cycle) == round_order(n, 0));  // the cycle repeats
    }
    CHECK(round_order(0, 3).empty());
}
