#include "config/population_overrides.hpp"

#include "core/error.hpp"
#include "scene/population_kind.hpp"

#include <fmt/format.h>

#include <memory>
#include <stdexcept>

namespace canopy {

void override_population_params(Population& population, const std::map<std::string, ParamValue>& overrides,
                                const std::map<std::string, int>& lines, const SourceLocation& where) {
    const PopulationKind* kind = population.family ? PopulationKindRegistry::instance().find(population.kind) : nullptr;
    if (!kind)
        throw ConfigError(where.file, where.line,
                          fmt::format("population '{}' is of kind '{}', which has no parameters to change", population.name,
                                      population.kind),
                          "populations = { ... } changes the params of a family's population kind");
    std::map<std::string, ParamValue> given(population.params.values().begin(), population.params.values().end());
    for (const auto& [name, value] : overrides) given[name] = value;
    population.params = ParamSet::resolve(kind->params(), given, lines, where, fmt::format("population kind '{}'", kind->name()));
    try {
        population.family = std::make_shared<const FamilyPopulation>(kind->generate(population.params, population.ground));
    } catch (const std::invalid_argument& e) {
        throw ConfigError(where.file, where.line,
                          fmt::format("population '{}' (kind '{}') cannot be generated: {}", population.name, kind->name(),
                                      e.what()),
                          "`canopy list` shows the kind's parameters and their ranges");
    }
}

}  // namespace canopy
