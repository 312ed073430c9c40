// The base of every shadow technique: it plans its maps and filters (ShadowPlan, pure data that
// the family's tests inspect) and runs on the family's frame graph built from that plan.
#pragma once

#include "core/technique.hpp"
#include "shadow_family.hpp"
#include "shadow_graph.hpp"
#include "shadow_plan.hpp"

namespace canopy {

class ShadowTechnique : public Technique {
public:
    virtual ShadowPlan plan(const ParamSet& params) const = 0;
    FrameGraph graph(const ParamSet& params) const final { return shadow_graph(plan(params)); }
    ErrorColumns error_columns() const override { return kShadowErrorColumns; }
    std::vector<std::string> pareto_errors() const override { return shadow_pareto_errors(); }
};

}  // namespace canopy
