#include "render/frame_renderer.hpp"

#include "core/pixel_visibility.hpp"
#include "gpu/format_names.hpp"
#include "graph/graph_readback.hpp"
#include "render/frame_uniforms.hpp"
#include "scene/camera.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <set>

#include <cmath>
#include <cstring>
#include <stdexcept>

namespace canopy {

namespace {

// Hints by cause: what the user can change so that the case runs.
std::string scene_hint(const SourceLocation& where, const std::string& change) {
    if (where.file.empty()) return change;
    return where.line > 0 ? fmt::format("{} ({}:{})", change, where.file.string(), where.line)
                          : fmt::format("{} ({})", change, where.file.string());
}

std::string device_hint() {
    return "pick another device with --device (`canopy devices` lists them), or another format parameter of the "
           "technique if it has one";
}

// What `graph`'s uses of image `name` need of its format.
std::optional<Unsupported> check_image(const GpuContext& gpu, const FrameGraph& graph, const ImageDecl& image) {
    const VkFormatFeatureFlags2 features = gpu.format_features(image.format);
    const std::string device = gpu.info().name, name = format_name(image.format);
    for (const PassDecl& p : graph.passes)
        for (const ResourceUse& u : p.uses) {
            if (u.resource != image.name) continue;
            const auto lacks = [&](VkFormatFeatureFlags2 bit) { return !(features & bit); };
            if (u.use == Use::depth_attachment &&
                (lacks(VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT) || lacks(VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT)))
                return Unsupported{fmt::format("device '{}' cannot render to and sample depth format {}", device, name),
                                   device_hint()};
            if ((u.use == Use::color_attachment || u.use == Use::resolve_target) &&
                lacks(VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT))
                return Unsupported{fmt::format("device '{}' cannot render to format {} (image '{}')", device, name, image.name),
                                   device_hint()};
            if (u.use == Use::sampled && u.sampler == SamplerKind::compare_linear &&
                lacks(VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT))
                return Unsupported{fmt::format("device '{}' has no depth-compare sampling for {} (needed by hardware PCF)",
                                               device, name),
                                   device_hint()};
            if (u.use == Use::sampled && (u.sampler == SamplerKind::linear || u.sampler == SamplerKind::linear_mipmap || u.sampler == SamplerKind::anisotropic) &&
                lacks(VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
                return Unsupported{fmt::format("device '{}' cannot filter format {} linearly (image '{}')", device, name,
                                               image.name),
                                   device_hint()};
            if ((u.use == Use::storage_write || u.use == Use::storage_read) &&
                lacks(VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT))
                return Unsupported{fmt::format("device '{}' cannot write format {} from compute shaders (image '{}')",
                                               device, name, image.name),
                                   device_hint()};
            if (u.use == Use::storage_write && !gpu.storage_write_without_format())
                return Unsupported{fmt::format("device '{}' lacks shaderStorageImageWriteWithoutFormat (needed by pass '{}')",
                                               device, p.name),
                                   device_hint()};
        }
    return std::nullopt;
}

}  // namespace

std::optional<Unsupported> check_supported(const GpuContext& gpu, const Scene& scene, const FrameGraph& graph) {
    if (auto unsupported = check_scene_supported(scene, graph)) return unsupported;
    for (const ImageDecl& image : graph.images)
        if (auto unsupported = check_image(gpu, graph, image)) return unsupported;
    for (const PassDecl& p : graph.passes)
        for (const ResourceUse& u : p.uses)
            if (u.use == Use::indirect && !gpu.draw_indirect_count())
                return Unsupported{fmt::format("device '{}' lacks drawIndirectCount (needed by pass '{}')", gpu.info().name,
                                               p.name),
                                   device_hint()};
    if (!(gpu.format_features(kColorTargetFormat) & VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT))
        return Unsupported{fmt::format("device '{}' cannot render to RGBA32F", gpu.info().name), device_hint()};
    return std::nullopt;
}

std::optional<Unsupported> check_population_present(const Scene& scene, const FrameGraph& graph) {
    const std::vector<std::string>& kinds = graph.needs.populations;
    const bool holds_one = std::any_of(scene.populations.begin(), scene.populations.end(), [&](const Population& p) {
        return std::find(kinds.begin(), kinds.end(), p.kind) != kinds.end();
    });
    if (kinds.empty() || holds_one) return std::nullopt;
    return Unsupported{fmt::format("scene '{}' holds no '{}' population, which this technique renders", scene.name,
                                   fmt::join(kinds, "' or '")),
                       scene_hint({scene.file, 0}, fmt::format("add a [[population]] of kind '{}' to the scene "
                                                               "(configs/scenes/meadow.toml has one), or pick a "
                                                               "technique for what the scene holds (`canopy list` "
                                                               "shows what each renders)",
                                                               kinds.front()))};
}

std::optional<Unsupported> check_scene_supported(const Scene& scene, const FrameGraph& graph) {
    if (std::string problem = validate(graph); !problem.empty())
        return Unsupported{"the technique's frame graph is malformed: " + problem,
                           "a bug in the technique, please report it"};
    // Before the light checks: a population the technique cannot draw is refused whatever the light.
    for (const Population& population : scene.populations) {
        const std::vector<std::string>& kinds = graph.needs.populations;
        if (std::find(kinds.begin(), kinds.end(), population.kind) != kinds.end()) {
            if (!population.ground.terrain || graph.needs.populations_on_terrain) continue;
            return Unsupported{
                fmt::format("population '{}' of scene '{}' stands on the heightfield '{}', and this technique does not "
                            "follow a terrain",
                            population.name, scene.name, population.ground.name),
                scene_hint(population.where, "remove the population's `terrain`, or pick a technique that follows one "
                                             "(`canopy list`: \"stands populations on a terrain\")")};
        }
        return Unsupported{
            fmt::format("scene '{}' holds population '{}' of kind '{}', which this technique does not render ({})",
                        scene.name, population.name, population.kind,
                        kinds.empty() ? std::string("it renders no populations")
                                      : fmt::format("it renders '{}' populations", fmt::join(kinds, "', '"))),
            scene_hint(population.where, fmt::format("remove the [[population]] from the scene, or pick a technique "
                                                     "that renders '{}' populations (`canopy list` shows what each "
                                                     "renders)",
                                                     population.kind))};
    }
    if (scene.lights.size() != 1)
        return Unsupported{fmt::format("scene '{}' has {} lights; the raster lit pass shades exactly one light",
                                       scene.name, scene.lights.size()),
                           scene_hint({scene.file, 0}, "keep one [[light]] in the scene")};
    if (graph.needs.light_view_resolution || graph.needs.area_light) {
        const Light* light = scene.shadow_light();
        if (!light)
            return Unsupported{fmt::format("scene '{}' has no shadow-casting light (casts_shadows = false)", scene.name),
                               scene_hint(scene.lights.front().where, "set casts_shadows = true on the scene's light")};
        if (graph.needs.area_light && !light->is_area())
            return Unsupported{fmt::format("scene '{}': this technique needs an area light (rect or sphere) with a size",
                                           scene.name),
                               scene_hint(light->where,
                                          "give the shadow light a size: type = \"rect\" with size = [w, h], or "
                                          "type = \"sphere\" with radius = r")};
    }
    return std::nullopt;
}

std::optional<std::string> unsupported_reason(const GpuContext& gpu, const Scene& scene, const FrameGraph& graph) {
    if (auto unsupported = check_supported(gpu, scene, graph)) return std::move(unsupported->reason);
    return std::nullopt;
}

FrameRenderer::FrameRenderer(const GpuContext& gpu, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                             uint32_t width, uint32_t height, FrameGraph graph)
    : gpu_(gpu),
      scene_description_(scene),
      width_(width),
      height_(height),
      light_view_resolution_(graph.needs.light_view_resolution),
      shader_params_(graph.shader_params) {
    if (auto reason = unsupported_reason(gpu, scene, graph)) throw GpuError(*reason);
    scene_ = std::make_unique<GpuScene>(gpu, ledger_, scene, meshes, graph.needs.populations,
                                        graph.needs.population_copies_on_gpu);
    if (light_view_resolution_)
        light_view_ = compute_light_view(*scene.shadow_light(), scene_bounds(scene, meshes), *light_view_resolution_);
    // A multisampled target that some pass resolves into the camera target clears to the background
    // too, wherever it is cleared: grass.lod clears it in its first pass and resolves in its last.
    std::set<std::string> resolved_to_color;
    for (const PassDecl& pass : graph.passes) {
        const bool resolves = std::any_of(pass.uses.begin(), pass.uses.end(), [](const ResourceUse& use) {
            return use.use == Use::resolve_target && use.resource == graph_names::kColor;
        });
        if (resolves)
            for (const ResourceUse& use : pass.uses)
                if (use.use == Use::color_attachment) resolved_to_color.insert(use.resource);
    }
    for (PassDecl& pass : graph.passes)
        for (ResourceUse& use : pass.uses)
            if (use.clear && (use.resource == graph_names::kColor ||
                              (use.use == Use::color_attachment && resolved_to_color.count(use.resource))))
                *use.clear = {scene.background.r, scene.background.g, scene.background.b, (*use.clear)[3]};
    uniforms_ = Buffer(gpu, ledger_, "frame", sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    write_uniforms(scene.camera);
    executor_ = std::make_unique<GraphExecutor>(gpu, ledger_, std::move(graph), width, height, uniforms_, *scene_);
    const PhaseTiming load = executor_->run_load(FrameState{0, scene.camera});
    load_timing_ = FrameTiming{load.pass_gpu_ms, load.gpu_ms,        load.wall_ms,
                               load.pass_cpu_ms, load.record_cpu_ms, load.uploaded_bytes};
}

FrameRenderer::~FrameRenderer() = default;

void FrameRenderer::write_uniforms(const Camera& camera) {
    const Scene& scene = scene_description_;
    FrameUniforms u{};
    u.view = view_matrix(camera);
    u.view_proj = view_projection(camera, width_, height_);
    u.inverse_view_proj = glm::inverse(u.view_proj);
    u.camera_position = glm::vec4(camera.position, 1.0f);
    const float focal_pixels = 0.5f * float(height_) / std::tan(0.5f * glm::radians(camera.fov_y_degrees));
    u.viewport = glm::vec4(float(width_), float(height_), focal_pixels, 0.0f);
    u.ambient = glm::vec4(scene.ambient, 0.0f);

    const Light& light = scene.shadow_light() ? *scene.shadow_light() : scene.lights.front();
    u.light_position = glm::vec4(light.position, float(int(light.type)));
    u.light_axis = glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.spot_angle_degrees)));
    u.light_intensity = glm::vec4(light.color * light.intensity, 0.0f);
    const float second = light.type == LightType::sphere ? light.sphere_radius : light.rect_size.y;
    u.light_size = glm::vec4(light.size(), light.rect_size.x, second, 0.0f);
    if (light_view_) {
        u.light_view = light_view_->view;
        u.light_proj = light_view_->projection;
        const float range = light_view_->far_plane - light_view_->near_plane;
        u.shadow_depth_range = glm::vec4(light_view_->near_plane, light_view_->far_plane, 1.0f / range,
                                         light_view_->perspective ? 1.0f : 0.0f);
        const float resolution = float(*light_view_resolution_);
        u.shadow_texel = glm::vec4(resolution, 1.0f / resolution, light_view_->texel_world, 0.0f);
    }
    u.technique = shader_params_.block;
    for (size_t i = 0; i < shader_params_.offsets.size(); ++i) {
        u.sample_offsets[i / 2][int(2 * (i % 2))] = shader_params_.offsets[i][0];
        u.sample_offsets[i / 2][int(2 * (i % 2) + 1)] = shader_params_.offsets[i][1];
    }
    std::memcpy(uniforms_.mapped(), &u, sizeof(u));
    near_plane_ = camera.near_plane;
    far_plane_ = camera.far_plane;
}

FrameTiming FrameRenderer::render() { return render(FrameState{next_frame_, scene_description_.camera}); }

FrameTiming FrameRenderer::render(const FrameState& state) { return render_frame(state, false); }
FrameTiming FrameRenderer::render_counting_primitives(const FrameState& state) { return render_frame(state, true); }

FrameTiming FrameRenderer::render_frame(const FrameState& state, bool count_primitives) {
    write_uniforms(state.camera);
    const PhaseTiming t = executor_->run_frame(state, count_primitives);
    next_frame_ = state.frame_index + 1;
    return FrameTiming{t.pass_gpu_ms,   t.gpu_ms,         t.wall_ms,    t.pass_cpu_ms, t.record_cpu_ms,
                       t.uploaded_bytes, t.primitives, t.counters, t.pass_draws};
}

namespace {

// The colour target's texels as the image users see: alpha holds the technique's visibility or
// its population coverage (read_pixel_visibility), the image is opaque.
Image opaque_color(Image image) {
    for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 1.0f;
    return image;
}

// Stored depth is glm::perspective's (zero to one): z = f (d - n) / ((f - n) d) for view depth d,
// so d = f n / (f - z (f - n)); the clear value 1 (the far plane) means nothing was drawn.
Image pixel_visibility_image(const Image& rgba, const Image& depth, double n, double f) {
    namespace pv = pixel_visibility;
    Image image(rgba.width, rgba.height);
    for (size_t i = 0; i < size_t(rgba.width) * size_t(rgba.height); ++i) {
        float* p = &image.pixels[4 * i];
        const float z = depth.pixels[4 * i];
        const bool drawn = z < 1.0f;
        p[pv::kVisibility] = rgba.pixels[4 * i + 3];
        p[pv::kCoverage] = rgba.pixels[4 * i + 3];  // the same alpha, read as the family declares it
        p[pv::kViewDepth] = drawn ? float(f * n / (f - double(z) * (f - n))) : 0.0f;
        p[pv::kSurface] = drawn ? 1.0f : 0.0f;
    }
    return image;
}

}  // namespace

Image FrameRenderer::read_image(const std::string& name, uint32_t mip, uint32_t layer) const {
    return read_graph_image(gpu_, *executor_, name, mip, layer);
}

std::vector<std::byte> FrameRenderer::read_buffer(const std::string& name) const {
    return read_graph_buffer(gpu_, *executor_, name);
}

Image FrameRenderer::read_color() const { return opaque_color(read_image(graph_names::kColor)); }

Image FrameRenderer::read_pixel_visibility() const { return read_color_and_pixel_visibility().visibility; }

FrameRenderer::ColorAndVisibility FrameRenderer::read_color_and_pixel_visibility() const {
    Image rgba = read_image(graph_names::kColor);
    Image visibility = pixel_visibility_image(rgba, read_image(graph_names::kDepth), near_plane_, far_plane_);
    return {opaque_color(std::move(rgba)), std::move(visibility)};
}

MemoryUse FrameRenderer::memory() const {
    return {ledger_.bytes("technique"), ledger_.bytes("targets"), ledger_.bytes("scene"), ledger_.peak("technique")};
}

std::string FrameRenderer::shadow_sampler() const {
    const auto& report = executor_->graph().report;
    auto it = report.find("shadow_sampler");
    return it == report.end() ? "" : it->second;
}

}  // namespace canopy
