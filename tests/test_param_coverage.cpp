// Every parameter a technique declares reaches its shader struct or its plan: the inverse of
// pbrt's ReportUnused. A parameter that reaches neither is a config knob that silently changes
// nothing, and a sweep over it would measure the same case again and again.
#include "core/registry.hpp"
#include "param_block.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

using namespace canopy;

namespace {

// Values other than the default that a sweep might give: every other choice, the other boolean,
// the range's ends and middle.
std::vector<ParamValue> alternatives(const ParamSpec& spec) {
    std::vector<ParamValue> values;
    switch (spec.type) {
    case ParamType::boolean: values.push_back(!std::get<bool>(spec.default_value)); break;
    case ParamType::path: break;  // no technique declares one: a file is a scene's (a population's map)
    case ParamType::choice:
        for (const std::string& choice : spec.choices) values.push_back(choice);
        break;
    case ParamType::integer:
        for (double v : {spec.min, spec.max, std::round(0.5 * (spec.min + spec.max))}) values.push_back((long long)v);
        break;
    case ParamType::real:
        for (double v : {spec.min, spec.max, 0.5 * (spec.min + spec.max)}) values.push_back(v);
        break;
    }
    std::erase(values, spec.default_value);
    return values;
}

std::string hex(float x) {
    std::ostringstream out;
    out << std::hexfloat << x;
    return out.str();
}

// Everything a FrameGraph hands the harness, as text: two graphs with the same fingerprint render
// the same frame (describe() covers resources, passes, their uses and settings, and the needs;
// the parameter block's bytes and the sample offsets are added here).
std::string fingerprint(const FrameGraph& graph) {
    std::ostringstream out;
    out << describe(graph) << " block";
    for (std::byte b : graph.shader_params.block) out << ' ' << int(b);
    out << " offsets";
    for (const auto& o : graph.shader_params.offsets) out << ' ' << hex(o[0]) << ',' << hex(o[1]);
    return out.str();
}

ParamSet resolve(const Technique& t, const std::vector<ParamSpec>& specs, std::map<std::string, ParamValue> given = {}) {
    return ParamSet::resolve(specs, given, {}, SourceLocation{"test.toml", 1}, t.name());
}

// The declared parameters of `technique` that reach neither its shader struct nor its plan: a
// parameter that is a member of the block must change the member's bytes for some other value,
// any other parameter must change the frame graph.
std::vector<std::string> unreached_params(const Technique& technique) {
    const std::vector<ParamSpec> specs = technique.params();
    const FrameGraph base = technique.graph(resolve(technique, specs));
    const std::string base_fingerprint = fingerprint(base);
    std::vector<std::string> unreached;
    for (const ParamSpec& spec : specs) {
        const auto& layout = base.shader_params.layout;
        const auto member = std::find_if(layout.begin(), layout.end(), [&](const ParamBlockMember& m) {
            return m.name == spec.name && m.kind == ParamBlockMember::Kind::parameter;
        });
        bool reached = false;
        for (const ParamValue& value : alternatives(spec)) {
            const FrameGraph plan = technique.graph(resolve(technique, specs, {{spec.name, value}}));
            reached = reached || (member != layout.end()
                                      ? std::memcmp(plan.shader_params.block.data() + member->offset,
                                                    base.shader_params.block.data() + member->offset, 4) != 0
                                      : fingerprint(plan) != base_fingerprint);
        }
        if (!reached) unreached.push_back(spec.name);
    }
    return unreached;
}

// Two techniques that break the rule, each in one way, to show that the check sees it.
#define COVERAGE_TEST_PARAMS(SHADER, PLAN, DERIVED)                                 \
    SHADER(real, strength, (1.0, 0.0, 2.0), "read by the shader")                   \
    PLAN(integer, resolution, (64, 16, 128), "read by plan()")                      \
    PLAN(integer, forgotten, (3, 1, 9), "declared, read by nothing")                \
    DERIVED(real, twice_strength, "computed by plan()")
}  // namespace
CANOPY_BEGIN_NAMESPACE
CANOPY_PARAM_BLOCK(CoverageTestParams, COVERAGE_TEST_PARAMS)
CANOPY_END_NAMESPACE
namespace {

class CoverageTestTechnique : public Technique {
public:
    explicit CoverageTestTechnique(bool uploads_block) : uploads_block_(uploads_block) {}
    std::string name() const override { return "test.coverage"; }
    std::string summary() const override { return "test"; }
    std::string paper() const override { return "none"; }
    std::vector<ParamSpec> params() const override { return shader::CoverageTestParams::specs(); }
    ErrorColumns error_columns() const override { return {}; }
    FrameGraph graph(const ParamSet& params) const override {
        shader::CoverageTestParams block = shader::CoverageTestParams::from(params);
        block.twice_strength = 2.0f * block.strength;
        FrameGraph graph;
        graph.images.push_back({"map", VK_FORMAT_R32_SFLOAT, ImageExtent::square(uint32_t(params.integer("resolution")))});
        if (uploads_block_) graph.shader_params.set_block(block);
        return graph;
    }

private:
    bool uploads_block_;
};

}  // namespace

TEST_CASE("every registered technique's parameters each reach its shader struct or its plan") {
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        CAPTURE(t->name());
        const std::vector<std::string> unreached = unreached_params(*t);
        std::string names;
        for (const std::string& name : unreached) names += name + " ";
        CHECK_MESSAGE(unreached.empty(), "declared but changing them changes neither the shader struct nor the plan: ",
                      names);
    }
}

TEST_CASE("a parameter nothing reads, or a shader struct never uploaded, is reported") {
    CHECK(unreached_params(CoverageTestTechnique(true)) == std::vector<std::string>{"forgotten"});
    CHECK(unreached_params(CoverageTestTechnique(false)) == std::vector<std::string>{"strength", "forgotten"});
}

TEST_CASE("a parameter block: specs in list order, members std140-packed, from() copies shader parameters") {
    using shader::CoverageTestParams;
    const std::vector<ParamSpec> specs = CoverageTestParams::specs();
    REQUIRE(specs.size() == 3);
    CHECK(specs[0].name == "strength");
    CHECK(specs[0].type == ParamType::real);
    CHECK(specs[0].max == 2.0);
    CHECK(specs[1].name == "resolution");
    CHECK(specs[2].doc == "declared, read by nothing");
    const auto layout = CoverageTestParams::layout();
    REQUIRE(layout.size() == 2);  // strength, twice_strength: PLAN parameters are no members
    CHECK(layout[0].name == "strength");
    CHECK(layout[0].offset == 0);
    CHECK(layout[0].kind == ParamBlockMember::Kind::parameter);
    CHECK(layout[1].name == "twice_strength");
    CHECK(layout[1].offset == 4);
    CHECK(layout[1].kind == ParamBlockMember::Kind::derived);
    const CoverageTestTechnique technique(true);
    const FrameGraph plan = technique.graph(resolve(technique, specs, {{"strength", 0.25}}));
    const auto block = plan.shader_params.get_block<CoverageTestParams>();
    CHECK(block.strength == 0.25f);
    CHECK(block.twice_strength == 0.5f);
}

TEST_CASE("every registered technique's block: members named once, within the uploaded bytes") {
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        CAPTURE(t->name());
        const std::vector<ParamSpec> specs = t->params();
        const FrameGraph plan = t->graph(resolve(*t, specs));
        const auto& layout = plan.shader_params.layout;
        for (size_t i = 0; i < layout.size(); ++i) {
            CAPTURE(layout[i].name);
            CHECK(layout[i].offset == 4 * i);
            CHECK(layout[i].offset + 4 <= kMaxParamBlockBytes);
            for (size_t j = 0; j < i; ++j) CHECK(layout[j].name != layout[i].name);
            // A derived member named like a parameter would hide whether the parameter is read.
            const bool is_param = std::any_of(specs.begin(), specs.end(), [&](const ParamSpec& s) { return s.name == layout[i].name; });
            CHECK(is_param == (layout[i].kind == ParamBlockMember::Kind::parameter));
        }
    }
}
