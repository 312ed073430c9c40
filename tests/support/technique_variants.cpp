#include "support/technique_variants.hpp"

#include "core/registry.hpp"

namespace canopy::test {

std::string family_of(const std::string& technique) { return technique.substr(0, technique.find('.')); }

std::vector<const Technique*> family_techniques(const std::string& family) {
    std::vector<const Technique*> chosen;
    for (const Technique* t : TechniqueRegistry::instance().all())
        if (family_of(t->name()) == family) chosen.push_back(t);
    return chosen;
}

std::vector<TechniqueVariant> technique_variants(const std::string& family) {
    std::vector<TechniqueVariant> all;
    for (const Technique* t : TechniqueRegistry::instance().all())
        if (family.empty() || family_of(t->name()) == family) all.push_back({t->name(), {}});
    const std::vector<TechniqueVariant> extra = {
        {"shadow.hard", {{"depth_format", std::string("d16")}}},
        {"shadow.pcf", {{"kernel", 5LL}, {"pattern", std::string("poisson")}}},
        {"shadow.pcf", {{"kernel", 3LL}, {"hardware_2x2", true}}},
        {"shadow.pcf", {{"kernel", 7LL}, {"receiver_plane", false}, {"depth_format", std::string("d16")}}},
        {"shadow.pcss", {{"blocker_search", 3LL}, {"kernel", 11LL}}},
        {"shadow.ssss", {{"kernel", 5LL}, {"lazy", false}}},
        {"shadow.vsm", {{"precision", std::string("fp16")}, {"bleeding_reduction", 0.3}}},
        {"shadow.esm", {{"log_space", true}}},
        {"shadow.esm", {{"precision", std::string("fp16")}, {"exponent", 10.0}}},
        {"shadow.gauss-cdf", {{"exact_erf", true}, {"filter", 1LL}}},
        {"shadow.power-cdf", {{"precision", std::string("fp16")}}},
        {"shadow.evsm", {{"components", std::string("2")}, {"precision", std::string("fp16")}}},
        {"shadow.msm", {{"precision", std::string("fp16")}, {"moment_bias", 6e-5}}},
        {"shadow.msm", {{"precision", std::string("unorm16")}, {"moment_bias", 6e-5}}},
        {"grass.geometry", {{"samples", 1LL}, {"coverage", std::string("alpha_test")}}},
        {"grass.geometry", {{"coverage", std::string("alpha_test")}}},
        {"grass.geometry", {{"culling", std::string("gpu")}, {"max_distance", 3.0}}},
        {"grass.billboard", {{"orientation", std::string("camera_facing")}, {"resolution", 64LL}}},
        {"grass.image", {{"resolution", 64LL}, {"slice_height", 0.01}}},
        {"grass.volume", {{"slices", 1LL}, {"resolution", 32LL}, {"height_resolution", 8LL}}},
        {"grass.image", {{"resolution", 64LL}, {"macro_cells", 2LL}}},
        {"grass.volume", {{"slices", 4LL}, {"resolution", 32LL}, {"height_resolution", 16LL}, {"macro_cells", 3LL}}},
        {"grass.slices", {{"slices", 1LL}, {"resolution", 32LL}, {"height_resolution", 8LL}, {"neighbours", false}}},
        {"grass.lod", {{"middle", std::string("slices")}, {"samples", 1LL}, {"coverage", std::string("alpha_test")},
                       {"slices", 2LL}, {"resolution", 32LL}, {"height_resolution", 8LL}, {"image_resolution", 32LL}}},
        {"grass.lod", {{"culling", std::string("quadtree")}, {"slices", 2LL}, {"resolution", 32LL},
                       {"height_resolution", 8LL}, {"image_resolution", 32LL}, {"middle_macro_max", 4LL}}},
    };
    for (const TechniqueVariant& v : extra)
        if (family.empty() || family_of(v.technique) == family) all.push_back(v);
    return all;
}

std::string describe(const TechniqueVariant& variant) {
    std::string out = variant.technique;
    for (const auto& [name, value] : variant.params) out += " " + name + "=" + to_string(value);
    return out;
}

}  // namespace canopy::test
