// The technique settings the integration tests render: every registered technique with its
// defaults, plus the non-default settings most likely to break (other formats, kernels,
// patterns, precisions, sample counts). Used by test_render (the shadow family: shadows,
// determinism) and test_validation (every family, each on a scene it renders).
#pragma once

#include "core/param.hpp"
#include "core/technique.hpp"

#include <map>
#include <string>
#include <vector>

namespace canopy::test {

struct TechniqueVariant {
    std::string technique;
    std::map<std::string, ParamValue> params;  // the rest at their defaults
};

// `family` ("shadow", "grass"): only that family's techniques (named "<family>.*"); empty: all.
std::vector<TechniqueVariant> technique_variants(const std::string& family = "");

// The registered techniques of one family, sorted by name: tests of what a family promises
// (shadows under occluders, isolated error) run over these, not over every technique.
std::vector<const Technique*> family_techniques(const std::string& family);

// "shadow.pcf" -> "shadow".
std::string family_of(const std::string& technique);

// "shadow.pcf kernel=5 pattern=poisson"
std::string describe(const TechniqueVariant& variant);

}  // namespace canopy::test
