// What the shadow techniques plan for given parameters, without rendering: the shadow map, PCF's
// taps and its Poisson tables.
#include "core/error.hpp"
#include "core/registry.hpp"
#include "../common/shadow_technique.hpp"
#include "../common/poisson_disk.hpp"
#include "../pcf/pcf_params.h"

#include <doctest/doctest.h>

#include <cmath>

using namespace canopy;

namespace {

ParamSet resolve(const Technique& t, std::map<std::string, ParamValue> given = {}) {
    return ParamSet::resolve(t.params(), given, {}, SourceLocation{"test.toml", 1}, t.name());
}

}  // namespace

TEST_CASE("shadow-map parameters reach the plan") {
    const auto& hard = dynamic_cast<const ShadowTechnique&>(*TechniqueRegistry::instance().find("shadow.hard"));
    const ShadowPlan plan = hard.plan(resolve(hard, {{"resolution", 512LL}, {"depth_format", std::string("d16")}}));
    REQUIRE(plan.shadow_map.has_value());
    CHECK(plan.shadow_map->resolution == 512);
    CHECK(plan.shadow_map->format == DepthFormat::d16);
    CHECK_FALSE(plan.shadow_map->compare_sampler);
}

TEST_CASE("PCF plans k*k samples and its Poisson tables fit the uniform block for every kernel") {
    const auto& pcf = dynamic_cast<const ShadowTechnique&>(*TechniqueRegistry::instance().find("shadow.pcf"));
    for (long long k = 1; k <= 11; ++k) {
        CAPTURE(k);
        const ShadowPlan grid = pcf.plan(resolve(pcf, {{"kernel", k}}));
        CHECK(grid.shader_params.get_block<shader::PcfParams>().count == k * k);
        CHECK(grid.shader_params.offsets.empty());
        const ShadowPlan poisson = pcf.plan(resolve(pcf, {{"kernel", k}, {"pattern", std::string("poisson")}}));
        CHECK(poisson.shader_params.offsets.size() == size_t(k * k));
        CHECK(poisson.shader_params.offsets.size() <= ShaderParams::kMaxOffsets);
    }
    const ShadowPlan hardware = pcf.plan(resolve(pcf, {{"hardware_2x2", true}}));
    CHECK(hardware.shadow_map->compare_sampler);
    CHECK_THROWS_AS(resolve(pcf, {{"kernel", 12LL}}), ConfigError);
}

TEST_CASE("Poisson disk: inside the unit disk, deterministic, well spread") {
    const auto a = poisson_disk(25, 7);
    const auto b = poisson_disk(25, 7);
    REQUIRE(a.size() == 25);
    CHECK(a == b);
    float min_distance = 10.0f;
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(a[i][0] * a[i][0] + a[i][1] * a[i][1] <= 1.0f + 1e-6f);
        for (size_t j = 0; j < i; ++j)
            min_distance = std::min(min_distance, std::hypot(a[i][0] - a[j][0], a[i][1] - a[j][1]));
    }
    // Uniform random points would typically have pairs closer than 0.05; the ideal spacing is ~0.35.
    CHECK(min_distance > 0.2f);
}

TEST_CASE("every shadow technique declares the visibility and shadow-region error columns") {
    // The family keeps the scene's surfaces and only computes the light's visibility, which the
    // lit pass multiplies into the irradiance: both groups measure its shadow (shadow_family.hpp).
    int shadow_techniques = 0;
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        if (t->name().rfind("shadow.", 0) != 0) continue;
        CAPTURE(t->name());
        ++shadow_techniques;
        CHECK(t->error_columns().visibility);
        CHECK(t->error_columns().shadow_regions);
    }
    CHECK(shadow_techniques == 10);
}
