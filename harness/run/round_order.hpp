// The order in which a group's cases take their turn in each measured round. A fixed order
// (A B C, A B C, ...) would let two things masquerade as a difference between techniques: a case
// that always runs after the same heavy one inherits its cache and thread state, and a case that
// always runs last in a round sees any drift within the round first. A Williams design (Williams
// 1949, the balanced Latin square of crossover trials) cycles through orders in which every case
// is at every position equally often and directly follows every other case equally often: n orders
// for an even number n of cases, 2n for an odd one. With a number of rounds that is not a multiple
// of that, the balance is as close as the rounds allow.
#pragma once

#include <cstddef>
#include <vector>

namespace canopy {

// How many rounds one balanced cycle takes: n for even n, 2n for odd n > 1, 1 for n <= 1.
size_t williams_cycle(size_t n);

// The order of round `round` (0-based): a permutation of 0..n-1.
std::vector<size_t> round_order(size_t n, size_t round);

}  // namespace canopy
