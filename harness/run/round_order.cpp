#include "run/round_order.hpp"

#include <algorithm>

namespace canopy {

size_t williams_cycle(size_t n) { return n <= 1 ? 1 : n % 2 == 0 ? n : 2 * n; }

std::vector<size_t> round_order(size_t n, size_t round) {
    if (n == 0) return {};
    // First row 0, 1, n-1, 2, n-2, ...; row i adds i (mod n); for odd n the reversed rows follow.
    std::vector<size_t> first;
    first.reserve(n);
    for (size_t k = 0, low = 1, high = n - 1; k < n; ++k) {
        if (k == 0) first.push_back(0);
        else if (k % 2 == 1) first.push_back(low++);
        else first.push_back(high--);
    }
    const size_t row = round % williams_cycle(n);
    std::vector<size_t> order(n);
    for (size_t k = 0; k < n; ++k) order[k] = (first[k] + row) % n;
    if (n % 2 == 1 && row >= n) {
        for (size_t k = 0; k < n; ++k) order[k] = (first[k] + row - n) % n;
        std::reverse(order.begin(), order.end());
    }
    return order;
}

}  // namespace canopy
