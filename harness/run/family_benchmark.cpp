#include "run/family_benchmark.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy {

FamilyBenchmarkRegistry& FamilyBenchmarkRegistry::instance() {
    static FamilyBenchmarkRegistry registry;
    return registry;
}

void FamilyBenchmarkRegistry::add(std::unique_ptr<FamilyBenchmark> benchmark) {
    for (const auto& b : benchmarks_)
        if (b->name() == benchmark->name())
            throw std::logic_error(fmt::format("family benchmark '{}' registered twice", benchmark->name()));
    benchmarks_.push_back(std::move(benchmark));
}

std::vector<const FamilyBenchmark*> FamilyBenchmarkRegistry::all() const {
    std::vector<const FamilyBenchmark*> out;
    for (const auto& b : benchmarks_) out.push_back(b.get());
    std::sort(out.begin(), out.end(), [](const FamilyBenchmark* a, const FamilyBenchmark* b) { return a->name() < b->name(); });
    return out;
}

}  // namespace canopy
