#include "mip_passes.hpp"

#include "graph/pass_context.hpp"

#include "shaders/grass/grass_mip_bleed_alone_comp.h"
#include "shaders/grass/grass_mip_bleed_comp.h"
#include "shaders/grass/grass_mip_coverage_comp.h"
#include "shaders/grass/grass_mip_reduce_alone_comp.h"
#include "shaders/grass/grass_mip_reduce_comp.h"

#include <fmt/format.h>
#include <glm/glm.hpp>

#include <algorithm>
#include <span>
#include <stdexcept>

namespace canopy::grass {

uint32_t SliceFiltering::resolve_levels() const {
    uint32_t levels = 0;
    for (uint32_t f = supersampling; f > 1; f /= 2) ++levels;
    return levels;
}

SliceFiltering slice_filtering(const ParamSet& params) {
    SliceFiltering f;
    const std::string filter = params.choice("mip_filter");
    if (filter == "none") f.filter = std::nullopt;
    else if (filter == "box") f.filter = MipFilter::box;
    else if (filter == "max_alpha") f.filter = MipFilter::max_alpha;
    else if (filter == "coverage") f.filter = MipFilter::coverage;
    else throw std::invalid_argument(fmt::format("slice_filtering: unknown mip_filter \"{}\"", filter));
    f.bleed = params.boolean("mip_bleed");
    f.anisotropic = params.boolean("mip_anisotropic");
    f.supersampling = uint32_t(params.integer("bake_supersampling"));
    return f;
}

std::optional<ParamConflict> slice_filtering_conflict(const ParamSet& params) {
    const long long s = params.integer("bake_supersampling");
    if (s != 1 && s != 2 && s != 4)
        return ParamConflict{{"bake_supersampling"}, fmt::format("bake_supersampling = {}: the bake resolves by halves", s),
                             "bake_supersampling = 1, 2 or 4"};
    return std::nullopt;
}

uint32_t mip_levels(uint32_t width, uint32_t height, const SliceFiltering& filtering) {
    const uint32_t resolve = filtering.resolve_levels();
    if (!filtering.filter) return 1 + resolve;
    uint32_t levels = 1;
    for (uint32_t side = std::max(width, height) * filtering.supersampling; side > 1; side /= 2) ++levels;
    return levels;
}

ImageExtent bake_extent(uint32_t width, uint32_t height, const SliceFiltering& filtering) {
    return ImageExtent::texels(width * filtering.supersampling, height * filtering.supersampling);
}

ResourceUse sampled_slices(const std::string& image, int binding, const SliceFiltering& filtering) {
    ResourceUse u{.resource = image, .use = Use::sampled, .binding = binding};
    u.sampler = !filtering.filter    ? SamplerKind::nearest
                : filtering.anisotropic ? SamplerKind::anisotropic
                                        : SamplerKind::linear_mipmap;
    u.range = Subresource{.mip = filtering.resolve_levels()};
    return u;
}

namespace {

ResourceUse at_mip(const std::string& image, Use how, int binding, uint32_t mip) {
    ResourceUse u{.resource = image, .use = how, .binding = binding};
    u.range = Subresource{.mip = mip, .mip_count = 1};
    return u;
}

uint32_t groups(uint32_t texels) { return std::max(1u, (texels + 7) / 8); }

// A pass's uses of the colour, blade map and (where there is one) companion, as grass_mip_*.glsl
// bind them: each at level `from` (bindings 1, 5, 3) used as `first`, and at level `to` (bindings
// 2, 6, 4) used as `second`.
void use_chain_levels(PassDecl& pass, const SliceMipChain& c, uint32_t from, Use first, uint32_t to, Use second) {
    const bool companion = !c.companion.empty();
    pass.uses = {at_mip(c.colour, first, 1, from), at_mip(c.colour, second, 2, to), at_mip(c.blades, first, 5, from),
                 at_mip(c.blades, second, 6, to)};
    if (companion) {
        pass.uses.push_back(at_mip(c.companion, first, 3, from));
        pass.uses.push_back(at_mip(c.companion, second, 4, to));
    }
}

// A record that pushes `constants` and runs `spirv` over a level of `s` texels and `z` layers.
auto dispatch_over(glm::ivec4 constants, glm::uvec2 s, uint32_t z, std::span<const uint32_t> spirv) {
    return [constants, s, z, spirv](PassContext& pc) {
        pc.push_constants(&constants, sizeof(constants));
        pc.dispatch(pc.compute_pipeline(spirv), groups(s.x), groups(s.y), z);
    };
}

int filter_code(MipFilter f) { return f == MipFilter::box ? 0 : f == MipFilter::max_alpha ? 1 : 2; }
constexpr int kResolve = 3;  // grass_mip_reduce.glsl's filter 3

}  // namespace

void declare_mip_passes(FrameGraph& g, const SliceMipChain& c) {
    const SliceFiltering& f = c.filtering;
    const uint32_t levels = mip_levels(c.width, c.height, f), resolved = f.resolve_levels();
    const bool companion = !c.companion.empty();
    const uint32_t per_layer = companion ? std::max(c.companions, 1u) : 1u;
    const uint32_t fine_w = c.width * f.supersampling, fine_h = c.height * f.supersampling;
    const auto size = [&](uint32_t mip) { return glm::uvec2(std::max(fine_w >> mip, 1u), std::max(fine_h >> mip, 1u)); };
    for (uint32_t l = 1; l < levels; ++l) {
        const bool resolving = l <= resolved;
        const int code = resolving ? kResolve : filter_code(*f.filter);
        PassDecl reduce{.name = fmt::format("{}mip_{}", c.pass_prefix, l), .kind = PassKind::compute, .phase = Phase::load};
        use_chain_levels(reduce, c, l - 1, Use::storage_read, l, Use::storage_write);
        reduce.push_constant_bytes = sizeof(glm::ivec4);
        reduce.settings = fmt::format("{} x {} x {} from the level above, {}", size(l).x, size(l).y, c.layers,
                                      resolving ? "resolving the supersampled bake" : to_string(*f.filter));
        reduce.record = dispatch_over(glm::ivec4(code, int(c.layers), int(per_layer), 0), size(l), c.layers * per_layer,
                                      companion ? std::span<const uint32_t>(grass_mip_reduce_comp)
                                                : std::span<const uint32_t>(grass_mip_reduce_alone_comp));
        g.passes.push_back(std::move(reduce));
        if (resolving || *f.filter != MipFilter::coverage) continue;
        PassDecl rescale{.name = fmt::format("{}mip_{}_coverage", c.pass_prefix, l), .kind = PassKind::compute,
                         .phase = Phase::load};
        rescale.uses = {at_mip(c.colour, Use::storage_read, 1, resolved), at_mip(c.colour, Use::storage_write, 2, l)};
        rescale.settings = fmt::format("alphas scaled to level {}'s coverage at a_r = 0.5, one workgroup per layer", resolved);
        rescale.record = [layers = c.layers](PassContext& pc) {
            pc.dispatch(pc.compute_pipeline(grass_mip_coverage_comp), layers, 1, 1);
        };
        g.passes.push_back(std::move(rescale));
    }
    if (!f.filter) return;  // NEAREST reads the resolved level alone
    // From the smallest level up to the resolved one: level l reads level l + 1 bled already.
    for (uint32_t l = levels - 1; l-- > resolved;) {
        PassDecl bleed{.name = fmt::format("{}mip_{}_bleed", c.pass_prefix, l), .kind = PassKind::compute,
                       .phase = Phase::load};
        use_chain_levels(bleed, c, l, Use::storage_write, l + 1, Use::storage_read);
        bleed.push_constant_bytes = sizeof(glm::ivec4);
        bleed.settings = f.bleed ? "colour, companion and blade map from the level below"
                                 : "blade map from the level below (mip_bleed = false)";
        bleed.record = dispatch_over(glm::ivec4(f.bleed ? 1 : 0, int(c.layers), int(per_layer), 0), size(l),
                                     c.layers * per_layer,
                                     companion ? std::span<const uint32_t>(grass_mip_bleed_comp)
                                               : std::span<const uint32_t>(grass_mip_bleed_alone_comp));
        g.passes.push_back(std::move(bleed));
    }
}

}  // namespace canopy::grass
