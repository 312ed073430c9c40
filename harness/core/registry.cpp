#include "core/registry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy {

TechniqueRegistry& TechniqueRegistry::instance() {
    // Function-local static: constructed on first use, so static registrations in other
    // translation units never see an unconstructed registry.
    static TechniqueRegistry registry;
    return registry;
}

void TechniqueRegistry::add(std::unique_ptr<Technique> technique) {
    if (!technique) throw std::logic_error("TechniqueRegistry::add: null technique");
    const std::string name = technique->name();
    if (find(name)) throw std::logic_error(fmt::format("technique '{}' is registered twice", name));
    if (!technique->error_columns().consistent())
        throw std::logic_error(fmt::format("technique '{}' declares visibility and coverage columns: its colour "
                                           "target's alpha can carry only one (core/error_columns.hpp)", name));
    techniques_.push_back(std::move(technique));
}

const Technique* TechniqueRegistry::find(const std::string& name) const {
    for (const auto& technique : techniques_)
        if (technique->name() == name) return technique.get();
    return nullptr;
}

std::vector<const Technique*> TechniqueRegistry::all() const {
    std::vector<const Technique*> sorted;
    for (const auto& technique : techniques_) sorted.push_back(technique.get());
    std::sort(sorted.begin(), sorted.end(),
              [](const Technique* a, const Technique* b) { return a->name() < b->name(); });
    return sorted;
}

std::vector<std::string> TechniqueRegistry::names() const {
    std::vector<std::string> names;
    for (const Technique* technique : all()) names.push_back(technique->name());
    return names;
}

}  // namespace canopy
