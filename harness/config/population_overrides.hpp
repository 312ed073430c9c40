// A family population's parameters replaced and its copies generated again: a scene variant's
// `populations = { grass = { blades = 1000 } }`, or a benchmark's field of another size.
#pragma once

#include "core/param.hpp"
#include "scene/population.hpp"

#include <map>
#include <string>

namespace canopy {

// `overrides` replace those of `population`'s parameters (the others kept), checked against its
// kind's specs; then its copies are generated again. Throws ConfigError at `where` (with an
// override's own line when `lines` has it) for a population of no family kind, an unknown name,
// a wrong type or range, or values that together cannot be generated.
void override_population_params(Population& population, const std::map<std::string, ParamValue>& overrides,
                                const std::map<std::string, int>& lines, const SourceLocation& where);

}  // namespace canopy
