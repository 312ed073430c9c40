// shadow.pcf: percentage-closer filtering over a grid or Poisson-disk kernel.
#include "core/registry.hpp"
#include "shaders/pcf_frag.h"
#include "../common/poisson_disk.hpp"
#include "../common/shadow_map_params.hpp"
#include "../common/shadow_family.hpp"

#include <algorithm>

namespace canopy {
namespace {

class PcfShadows final : public Technique {
public:
    std::string name() const override { return "shadow.pcf"; }
    std::string summary() const override { return "percentage-closer filtering: average of k*k depth tests"; }
    std::string paper() const override { return "Reeves, Salesin, Cook 1987; Gumbau 2011 Table 6.1 'PCF 3x3'"; }

    std::vector<ParamSpec> params() const override {
        auto specs = shadow_map_params();
        specs.push_back(ParamSpec::integer("kernel", 3, 1, 11, "kernel width k: k*k depth tests per pixel"));
        specs.push_back(ParamSpec::choice("pattern", "grid", {"grid", "poisson"},
                                          "sample layout: k x k texel grid, or k*k Poisson-disk samples of radius k/2"));
        specs.push_back(ParamSpec::boolean("hardware_2x2", false,
                                           "each sample is a bilinear 2x2 depth compare (LINEAR compare sampler)"));
        specs.push_back(ParamSpec::boolean("receiver_plane", true,
                                           "compare each tap with the receiver plane's depth there (else bias for the whole kernel)"));
        return specs;
    }

    ErrorColumns error_columns() const override { return kShadowErrorColumns; }

    FramePlan plan(const ParamSet& params) const override {
        const int kernel = int(params.integer("kernel"));
        const bool poisson = params.choice("pattern") == "poisson";
        const bool hardware = params.boolean("hardware_2x2");
        const int count = kernel * kernel;
        // Grid taps reach (k-1)/2 texels from the centre; the Poisson disk is inscribed in the
        // grid's k-texel footprint. A bilinear tap reaches half a texel further.
        const float reach = (poisson ? 0.5f * float(kernel) : 0.5f * float(kernel - 1)) + (hardware ? 0.5f : 0.0f);

        FramePlan plan;
        plan.shadow_map = shadow_map_needs(params);
        plan.shadow_map->compare_sampler = hardware;
        plan.forward_fragment_spirv = pcf_frag;
        write_bias_params(params, plan.shader_params);
        plan.shader_params.values[2] = float(kernel);
        plan.shader_params.values[3] = poisson ? 1.0f : 0.0f;
        plan.shader_params.values[4] = hardware ? 1.0f : 0.0f;
        plan.shader_params.values[5] = float(count);
        plan.shader_params.values[6] = reach;
        plan.shader_params.values[7] = params.boolean("receiver_plane") ? 1.0f : 0.0f;
        if (poisson) plan.shader_params.offsets = poisson_disk(count);
        return plan;
    }
};

RegisterTechnique<PcfShadows> registered;

}  // namespace
}  // namespace canopy
