// shadow.pcf: percentage-closer filtering over a grid or Poisson-disk kernel.
#include "core/registry.hpp"
#include "shaders/shadow/pcf_frag.h"
#include "pcf_params.h"
#include "../common/poisson_disk.hpp"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_technique.hpp"

#include <algorithm>

namespace canopy {
namespace {

class PcfShadows final : public ShadowTechnique {
public:
    std::string name() const override { return "shadow.pcf"; }
    std::string summary() const override { return "percentage-closer filtering: average of k*k depth tests"; }
    std::string paper() const override { return "Reeves, Salesin, Cook 1987; Gumbau 2011 Table 6.1 'PCF 3x3'"; }

    std::vector<ParamSpec> params() const override { return shader::PcfParams::specs(); }


    ShadowPlan plan(const ParamSet& params) const override {
        shader::PcfParams block = shader::PcfParams::from(params);
        const bool poisson = block.pattern == PCF_PATTERN_POISSON;
        const bool hardware = block.hardware_2x2 != 0;
        block.count = block.kernel * block.kernel;
        // Grid taps reach (k-1)/2 texels from the centre; the Poisson disk is inscribed in the
        // grid's k-texel footprint. A bilinear tap reaches half a texel further.
        block.reach = (poisson ? 0.5f * float(block.kernel) : 0.5f * float(block.kernel - 1)) + (hardware ? 0.5f : 0.0f);

        ShadowPlan plan;
        plan.shadow_map = shadow_map_needs(params);
        plan.shadow_map->compare_sampler = hardware;
        plan.forward_fragment_spirv = pcf_frag;
        plan.shader_params.set_block(block);
        if (poisson) plan.shader_params.offsets = poisson_disk(block.count);
        return plan;
    }
};

RegisterTechnique<PcfShadows> registered;

}  // namespace
}  // namespace canopy
