// The technique settings the integration tests render: every registered technique with its
// defaults, plus the non-default settings most likely to break (other formats, kernels,
// patterns, precisions). Used by test_render (shadows, determinism) and test_validation.
#pragma once

#include "core/param.hpp"

#include <map>
#include <string>
#include <vector>

namespace canopy::test {

struct TechniqueVariant {
    std::string technique;
    std::map<std::string, ParamValue> params;  // the rest at their defaults
};

std::vector<TechniqueVariant> technique_variants();

// "shadow.pcf kernel=5 pattern=poisson"
std::string describe(const TechniqueVariant& variant);

}  // namespace canopy::test
