// The technique registry: every technique is found by name, documents itself and plans with its
// defaults, without rendering (what the shadow techniques plan: techniques/shadow/tests).
#include "core/registry.hpp"

#include <doctest/doctest.h>

#include <algorithm>

using namespace canopy;

namespace {

ParamSet resolve(const Technique& t, std::map<std::string, ParamValue> given = {}) {
    return ParamSet::resolve(t.params(), given, {}, SourceLocation{"test.toml", 1}, t.name());
}

}  // namespace

TEST_CASE("both first shadow techniques are registered by name") {
    const auto& registry = TechniqueRegistry::instance();
    REQUIRE(registry.find("shadow.hard") != nullptr);
    REQUIRE(registry.find("shadow.pcf") != nullptr);
    CHECK(registry.find("shadow.nope") == nullptr);
    const auto names = registry.names();
    CHECK(std::is_sorted(names.begin(), names.end()));
}

TEST_CASE("every technique's defaults resolve and every parameter is documented") {
    for (const Technique* t : TechniqueRegistry::instance().all()) {
        CAPTURE(t->name());
        CHECK_FALSE(t->summary().empty());
        CHECK_FALSE(t->paper().empty());
        for (const ParamSpec& p : t->params()) {
            CAPTURE(p.name);
            CHECK_FALSE(p.doc.empty());
        }
        // Its frame graph is well formed and draws (or resolves into) the camera's colour target.
        const FrameGraph graph = t->graph(resolve(*t));
        CHECK(validate(graph) == "");
        const bool draws_color = std::any_of(graph.passes.begin(), graph.passes.end(), [](const PassDecl& p) {
            return std::any_of(p.uses.begin(), p.uses.end(), [](const ResourceUse& u) {
                return u.resource == graph_names::kColor &&
                       (u.use == Use::color_attachment || u.use == Use::resolve_target);
            });
        });
        CHECK(draws_color);
    }
}
