// shadow.hard: standard shadow mapping with constant and slope-scaled bias.
#include "core/registry.hpp"
#include "shaders/shadow/hard_frag.h"
#include "hard_params.h"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_technique.hpp"

namespace canopy {
namespace {

class HardShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.hard"; }
    std::string summary() const override { return "shadow mapping: one depth test per pixel, hard edges"; }
    std::string paper() const override { return "Williams 1978; Gumbau 2011 Table 6.1 'standard'"; }
    std::vector<ParamSpec> params() const override { return shader::HardParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        ShadowPlan plan;
        plan.shadow_map = shadow_map_needs(params);
        plan.forward_fragment_spirv = hard_frag;
        plan.shader_params.set_block(shader::HardParams::from(params));
        return plan;
    }
};

RegisterTechnique<HardShadows> registered;

}  // namespace
}  // namespace canopy
