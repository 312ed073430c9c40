#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy {

PopulationKindRegistry& PopulationKindRegistry::instance() {
    // Constructed on first use, so registrations in other translation units never see it unbuilt.
    static PopulationKindRegistry registry;
    return registry;
}

void PopulationKindRegistry::add(std::unique_ptr<PopulationKind> kind) {
    if (!kind) throw std::logic_error("PopulationKindRegistry::add: null kind");
    const std::string name = kind->name();
    if (find(name) || name == population_kinds::kScatter)
        throw std::logic_error(fmt::format("population kind '{}' is registered twice", name));
    kinds_.push_back(std::move(kind));
}

const PopulationKind* PopulationKindRegistry::find(const std::string& name) const {
    for (const auto& kind : kinds_)
        if (kind->name() == name) return kind.get();
    return nullptr;
}

std::vector<const PopulationKind*> PopulationKindRegistry::all() const {
    std::vector<const PopulationKind*> sorted;
    for (const auto& kind : kinds_) sorted.push_back(kind.get());
    std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->name() < b->name(); });
    return sorted;
}

std::vector<std::string> PopulationKindRegistry::names() const {
    std::vector<std::string> names;
    for (const PopulationKind* kind : all()) names.push_back(kind->name());
    return names;
}

}  // namespace canopy
