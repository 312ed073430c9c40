#include "shadow_graph.hpp"

#include "graph/pass_context.hpp"
#include "render/frame_uniforms.hpp"

#include "shaders/harness/scene_vert.h"
#include "shaders/shadow/shadow_depth_frag.h"
#include "shaders/shadow/shadow_depth_vert.h"
#include "lit_pass_output.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace canopy {

namespace {

constexpr uint32_t kDrawConstants = sizeof(DrawConstants);

// Push constants of every separable filter (techniques/shadow/shaders/separable_filter.glsl).
struct FilterPushConstants {
    int32_t direction[2];
    int32_t radius;
    int32_t downsample;
    int32_t extent[2];      // output
    int32_t src_extent[2];  // input
};

std::string spirv_name(std::span<const uint32_t> spirv) {
    // Identity of a shader in a plan's description: its size and a hash of its words.
    uint64_t h = 1469598103934665603ull;
    for (uint32_t w : spirv) h = (h ^ w) * 1099511628211ull;
    return fmt::format("spirv:{}:{:016x}", spirv.size(), h);
}

ResourceUse frame_uniforms(int binding) { return {graph_names::kFrameUniforms, Use::uniform, binding}; }
ResourceUse sampled(const std::string& image, int binding, SamplerKind sampler = SamplerKind::nearest) {
    ResourceUse u{image, Use::sampled, binding};
    u.sampler = sampler;
    return u;
}
ResourceUse attachment(const std::string& image, Use use, std::array<float, 4> clear, bool store = true) {
    ResourceUse u{image, use};
    u.clear = clear;
    u.store = store;
    return u;
}

// The image each pass of a chain writes: one per pass when any pass downsamples, else `prefix`_a
// and `prefix`_b (or the source itself, with `write_back`) in turn.
std::vector<std::string> chain_outputs(const std::string& prefix, const std::string& source, bool write_back,
                                       const std::vector<FilterPass>& passes) {
    const bool per_pass = std::any_of(passes.begin(), passes.end(), [](const FilterPass& p) { return p.downsample > 1; });
    std::vector<std::string> outputs;
    for (size_t i = 0; i < passes.size(); ++i)
        outputs.push_back(per_pass ? fmt::format("{}_{}", prefix, i)
                          : i % 2 == 0 ? prefix + "_a"
                          : write_back ? source
                                       : prefix + "_b");
    return outputs;
}

}  // namespace

std::string add_filter_chain(FrameGraph& graph, const std::string& prefix, const std::string& source,
                             bool write_back, uint32_t width, uint32_t height, VkFormat format,
                             const std::vector<FilterPass>& passes, const FilterChainInputs& extras, bool screen_sized) {
    if (passes.empty()) return source;
    std::vector<VkExtent2D> extents{{width, height}};
    for (const FilterPass& pass : passes) {
        const uint32_t f = uint32_t(std::max(pass.downsample, 1));
        extents.push_back({std::max((extents.back().width + f - 1) / f, 1u), std::max((extents.back().height + f - 1) / f, 1u)});
    }
    if (screen_sized && std::any_of(passes.begin(), passes.end(), [](const FilterPass& p) { return p.downsample > 1; }))
        throw std::logic_error(fmt::format("filter chain '{}': a screen-sized chain cannot downsample", prefix));
    const std::vector<std::string> outputs = chain_outputs(prefix, source, write_back, passes);
    for (size_t i = 0; i < passes.size(); ++i) {
        if (outputs[i] == source || graph.image(outputs[i])) continue;  // declared once
        ImageDecl image{outputs[i], format};
        image.extent = screen_sized ? ImageExtent::screen() : ImageExtent::texels(extents[i + 1].width, extents[i + 1].height);
        graph.images.push_back(image);
    }
    for (size_t i = 0; i < passes.size(); ++i) {
        const FilterPass& pass = passes[i];
        PassDecl p{pass.name, PassKind::compute};
        const std::string input = i == 0 ? source : outputs[i - 1];
        p.uses.push_back(sampled(input, 0));
        p.uses.push_back({outputs[i], Use::storage_write, 1});
        if (extras.frame_uniforms) p.uses.push_back(frame_uniforms(2));
        if (!extras.shadow_depth.empty()) p.uses.push_back(sampled(extras.shadow_depth, 3));
        if (!extras.aux.empty()) p.uses.push_back(sampled(extras.aux, 4));
        p.push_constant_bytes = sizeof(FilterPushConstants);
        const VkExtent2D in = extents[i], out = extents[i + 1];
        const FilterPushConstants push{{pass.horizontal ? 1 : 0, pass.horizontal ? 0 : 1}, pass.radius,
                                       std::max(pass.downsample, 1), {int32_t(out.width), int32_t(out.height)},
                                       {int32_t(in.width), int32_t(in.height)}};
        const std::span<const uint32_t> spirv = pass.compute_spirv;
        p.settings = fmt::format("{} radius={} horizontal={} downsample={}", spirv_name(spirv), pass.radius,
                                 pass.horizontal, pass.downsample);
        // A screen-sized chain learns its extent when it runs (the camera target's size).
        const bool at_screen = screen_sized;
        const std::string output = outputs[i];
        p.record = [spirv, push, at_screen, input, output](PassContext& pc) {
            FilterPushConstants constants = push;
            if (at_screen) {
                const VkExtent2D src = pc.extent(input), dst = pc.extent(output);
                constants.src_extent[0] = int32_t(src.width), constants.src_extent[1] = int32_t(src.height);
                constants.extent[0] = int32_t(dst.width), constants.extent[1] = int32_t(dst.height);
            }
            pc.push_constants(&constants, sizeof(constants));
            pc.dispatch(pc.compute_pipeline(spirv), (uint32_t(constants.extent[0]) + 7) / 8,
                        (uint32_t(constants.extent[1]) + 7) / 8, 1);
        };
        graph.passes.push_back(std::move(p));
    }
    return outputs.back();
}

namespace {

// Raster state of a pass that draws the scene with `vertex` and `fragment`.
RasterState scene_state(std::span<const uint32_t> vertex, std::span<const uint32_t> fragment) {
    RasterState state;
    state.vertex_spirv = vertex;
    state.fragment_spirv = fragment;
    return state;
}

PassDecl scene_pass(const std::string& name, RasterState state, SceneFilter filter) {
    PassDecl p{name, PassKind::raster};
    p.push_constant_bytes = kDrawConstants;
    p.settings = fmt::format("{} {} {}", spirv_name(state.vertex_spirv), spirv_name(state.fragment_spirv),
                             filter == SceneFilter::shadow_casters ? "casters" : "all");
    p.record = [state, filter](PassContext& pc) {
        pc.bind(pc.raster_pipeline(state));
        pc.draw_scene(filter);
    };
    return p;
}

}  // namespace

namespace shadow_images {

namespace {
std::string chain_result(const std::string& prefix, const std::string& source, bool write_back,
                         const std::vector<FilterPass>& passes) {
    return passes.empty() ? source : chain_outputs(prefix, source, write_back, passes).back();
}
}  // namespace

std::string coarse_map(const ShadowPlan& plan) {
    return chain_result("coarse", kDepthMap, false, plan.shadow_map->coarse_filters);
}
std::string screen_shadow(const ShadowPlan& plan) {
    return chain_result("screen_filter", "screen_shadow", true, plan.screen_shadow->filters);
}
std::string moment_result(const ShadowPlan& plan) {
    return chain_result("moment_filter", kMomentMap, true, plan.moment_map->prefilter);
}

}  // namespace shadow_images

FrameGraph shadow_graph(const ShadowPlan& plan) {
    FrameGraph graph;
    graph.shader_params = plan.shader_params;
    graph.needs.area_light = plan.needs_area_light;
    const std::array<float, 4> far_depth{1.0f, 0.0f, 0.0f, 0.0f};
    std::vector<ResourceUse> light_maps;  // what the screen and lit passes sample

    if (plan.shadow_map) {
        const ShadowMapNeeds& needs = *plan.shadow_map;
        graph.needs.light_view_resolution = needs.resolution;
        graph.images.push_back({shadow_images::kDepthMap, vk_format(needs.format), ImageExtent::square(needs.resolution)});
        PassDecl p = scene_pass("shadow_map", scene_state(shadow_depth_vert, shadow_depth_frag), SceneFilter::shadow_casters);
        p.uses = {frame_uniforms(0), attachment(shadow_images::kDepthMap, Use::depth_attachment, far_depth)};
        graph.passes.push_back(std::move(p));
        light_maps.push_back(sampled(shadow_images::kDepthMap, 1));
        // Binding 2 is the same map through a LINEAR depth-compare sampler (hardware 2x2 PCF)
        // for techniques that ask for it, else through NEAREST (their shaders never sample it).
        light_maps.push_back(sampled(shadow_images::kDepthMap, 2,
                                     needs.compare_sampler ? SamplerKind::compare_linear : SamplerKind::nearest));
        graph.report["shadow_sampler"] = needs.compare_sampler ? "compare-linear" : "nearest";
        if (!needs.coarse_filters.empty()) {
            // The coarse passes may read the frame (e.g. the light's size).
            const std::string coarse =
                add_filter_chain(graph, "coarse", shadow_images::kDepthMap, false, needs.resolution, needs.resolution,
                                 VK_FORMAT_R32_SFLOAT, needs.coarse_filters, FilterChainInputs{true, "", ""}, false);
            light_maps.push_back(sampled(coarse, 4));
        }
    }
    if (plan.moment_map) {
        const MomentMapNeeds& needs = *plan.moment_map;
        graph.needs.light_view_resolution = needs.resolution;
        const VkFormat format = vk_format(needs.format);
        graph.images.push_back({shadow_images::kMomentMap, format, ImageExtent::square(needs.resolution)});
        graph.images.push_back({"moment_depth", VK_FORMAT_D32_SFLOAT, ImageExtent::square(needs.resolution)});
        PassDecl p = scene_pass("moment_map", scene_state(shadow_depth_vert, needs.fragment_spirv), SceneFilter::shadow_casters);
        p.uses = {frame_uniforms(0), attachment(shadow_images::kMomentMap, Use::color_attachment, needs.clear_value),
                  attachment("moment_depth", Use::depth_attachment, far_depth, false)};
        graph.passes.push_back(std::move(p));
        const std::string result = add_filter_chain(graph, "moment_filter", shadow_images::kMomentMap, true, needs.resolution,
                                                    needs.resolution, format, needs.prefilter, FilterChainInputs{}, false);
        light_maps.push_back(sampled(result, 3, SamplerKind::linear));
        graph.report["shadow_sampler"] = std::string("linear-") + to_string(needs.format);
    }
    if (plan.screen_shadow) {
        const ScreenShadowNeeds& needs = *plan.screen_shadow;
        graph.images.push_back({"screen_shadow", VK_FORMAT_R32G32B32A32_SFLOAT, ImageExtent::screen()});
        graph.images.push_back({"screen_normals", VK_FORMAT_R16G16B16A16_SFLOAT, ImageExtent::screen()});
        graph.images.push_back({"screen_depth", VK_FORMAT_D32_SFLOAT, ImageExtent::screen()});
        PassDecl p = scene_pass("screen_shadow", scene_state(scene_vert, needs.fragment_spirv), SceneFilter::all);
        p.uses = {frame_uniforms(0)};
        p.uses.insert(p.uses.end(), light_maps.begin(), light_maps.end());
        // Background: fully lit, no blur, infinitely far (so filters never mix it with surfaces).
        p.uses.push_back(attachment("screen_shadow", Use::color_attachment, {1.0f, 0.0f, 0.0f, 1e30f}));
        p.uses.push_back(attachment("screen_normals", Use::color_attachment, {0.0f, 0.0f, 0.0f, 0.0f}));
        p.uses.push_back(attachment("screen_depth", Use::depth_attachment, far_depth, false));
        graph.passes.push_back(std::move(p));
        const std::string result =
            add_filter_chain(graph, "screen_filter", "screen_shadow", true, 0, 0, VK_FORMAT_R32G32B32A32_SFLOAT,
                             needs.filters, FilterChainInputs{true, shadow_images::kDepthMap, "screen_normals"}, true);
        light_maps.push_back(sampled(result, 5));
    }
    PassDecl lit = scene_pass("lit", scene_state(scene_vert, plan.forward_fragment_spirv), SceneFilter::all);
    lit.uses = {frame_uniforms(0)};
    lit.uses.insert(lit.uses.end(), light_maps.begin(), light_maps.end());
    // Depth is stored: the technique-isolated error reads where each pixel centre hit.
    // The harness clears the colour target's rgb to the scene's background (graph_names::kColor).
    lit.uses.push_back(attachment(graph_names::kColor, Use::color_attachment, {0.0f, 0.0f, 0.0f, shader::VISIBILITY_NOT_LIT}));
    lit.uses.push_back(attachment(graph_names::kDepth, Use::depth_attachment, far_depth, true));
    graph.passes.push_back(std::move(lit));
    return graph;
}

}  // namespace canopy
