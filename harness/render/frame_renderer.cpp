#include "render/frame_renderer.hpp"

#include "gpu/rendering.hpp"
#include "core/pixel_visibility.hpp"
#include "render/texture_readback.hpp"
#include "scene/camera.hpp"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

namespace canopy {

namespace {

FrameUniforms make_uniforms(const Scene& scene, uint32_t width, uint32_t height, const FramePlan& plan,
                            const std::optional<LightView>& light_view) {
    FrameUniforms u{};
    const Camera& camera = scene.camera;
    u.view = view_matrix(camera);
    u.view_proj = projection_matrix(camera, float(width) / float(height)) * u.view;
    u.inverse_view_proj = glm::inverse(u.view_proj);
    u.camera_position = glm::vec4(camera.position, 1.0f);
    const float focal_pixels = 0.5f * float(height) / std::tan(0.5f * glm::radians(camera.fov_y_degrees));
    u.viewport = glm::vec4(float(width), float(height), focal_pixels, 0.0f);
    u.ambient = glm::vec4(scene.ambient, 0.0f);

    const Light& light = scene.shadow_light() ? *scene.shadow_light() : scene.lights.front();
    u.light_position = glm::vec4(light.position, float(int(light.type)));
    u.light_axis = glm::vec4(glm::normalize(light.direction), std::cos(glm::radians(light.spot_angle_degrees)));
    u.light_intensity = glm::vec4(light.color * light.intensity, 0.0f);
    const float second = light.type == LightType::sphere ? light.sphere_radius : light.rect_size.y;
    u.light_size = glm::vec4(light.size(), light.rect_size.x, second, 0.0f);

    const uint32_t map_resolution = plan.shadow_map ? plan.shadow_map->resolution
                                  : plan.moment_map ? plan.moment_map->resolution : 0;
    if (light_view) {
        u.light_view = light_view->view;
        u.light_proj = light_view->projection;
        const float range = light_view->far_plane - light_view->near_plane;
        u.shadow_depth_range = glm::vec4(light_view->near_plane, light_view->far_plane, 1.0f / range,
                                         light_view->perspective ? 1.0f : 0.0f);
        const float resolution = float(map_resolution);
        u.shadow_texel = glm::vec4(resolution, 1.0f / resolution, light_view->texel_world, 0.0f);
    }
    u.technique = plan.shader_params.block;
    for (size_t i = 0; i < plan.shader_params.offsets.size(); ++i) {
        u.sample_offsets[i / 2][int(2 * (i % 2))] = plan.shader_params.offsets[i][0];
        u.sample_offsets[i / 2][int(2 * (i % 2) + 1)] = plan.shader_params.offsets[i][1];
    }
    return u;
}

}  // namespace

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

}  // namespace

std::optional<Unsupported> check_supported(const GpuContext& gpu, const Scene& scene, const FramePlan& plan) {
    const auto needs_area_light = [&] {
        return Unsupported{fmt::format("scene '{}': this technique needs an area light (rect or sphere) with a size",
                                       scene.name),
                           scene_hint(scene.shadow_light()->where,
                                      "give the shadow light a size: type = \"rect\" with size = [w, h], or "
                                      "type = \"sphere\" with radius = r")};
    };
    const auto no_shadow_light = [&] {
        return Unsupported{fmt::format("scene '{}' has no shadow-casting light (casts_shadows = false)", scene.name),
                           scene_hint(scene.lights.front().where, "set casts_shadows = true on the scene's light")};
    };
    if (scene.lights.size() != 1)
        return Unsupported{fmt::format("scene '{}' has {} lights; the raster lit pass shades exactly one light",
                                       scene.name, scene.lights.size()),
                           scene_hint({scene.file, 0}, "keep one [[light]] in the scene")};
    if (plan.shadow_map) {
        const Light* light = scene.shadow_light();
        if (!light) return no_shadow_light();
        if (plan.needs_area_light && !light->is_area()) return needs_area_light();
        const VkFormat format = vk_format(plan.shadow_map->format);
        const VkFormatFeatureFlags2 features = gpu.format_features(format);
        const char* name = to_string(plan.shadow_map->format);
        if (!(features & VK_FORMAT_FEATURE_2_DEPTH_STENCIL_ATTACHMENT_BIT) || !(features & VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_BIT))
            return Unsupported{fmt::format("device '{}' cannot render to and sample depth format {}", gpu.info().name, name),
                               device_hint()};
        if (plan.shadow_map->compare_sampler && !(features & VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT))
            return Unsupported{fmt::format("device '{}' has no depth-compare sampling for {} (needed by hardware PCF)",
                                           gpu.info().name, name),
                               device_hint()};
    }
    if (plan.moment_map) {
        const Light* light = scene.shadow_light();
        if (!light) return no_shadow_light();
        if (plan.needs_area_light && !light->is_area()) return needs_area_light();
        const char* name = to_string(plan.moment_map->format);
        const VkFormatFeatureFlags2 features = gpu.format_features(vk_format(plan.moment_map->format));
        if (!(features & VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT))
            return Unsupported{fmt::format("device '{}' cannot render to moment format {}", gpu.info().name, name),
                               device_hint()};
        if (!(features & VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
            return Unsupported{fmt::format("device '{}' cannot filter moment format {} linearly", gpu.info().name, name),
                               device_hint()};
        if (!plan.moment_map->prefilter.empty()) {
            if (!(features & VK_FORMAT_FEATURE_2_STORAGE_IMAGE_BIT))
                return Unsupported{fmt::format("device '{}' cannot write moment format {} from compute shaders",
                                               gpu.info().name, name),
                                   device_hint()};
            if (!gpu.storage_write_without_format())
                return Unsupported{fmt::format("device '{}' lacks shaderStorageImageWriteWithoutFormat (needed by prefilters)",
                                               gpu.info().name),
                                   device_hint()};
        }
    }
    if (plan.screen_shadow && !plan.shadow_map)
        return Unsupported{"a screen-shadow pass needs a depth shadow map",
                           "the technique's plan is inconsistent: a bug in the technique, please report it"};
    const bool compute = (plan.shadow_map && !plan.shadow_map->coarse_filters.empty()) ||
                         (plan.screen_shadow && !plan.screen_shadow->filters.empty());
    if (compute && !gpu.storage_write_without_format())
        return Unsupported{fmt::format("device '{}' lacks shaderStorageImageWriteWithoutFormat (needed by filter passes)",
                                       gpu.info().name),
                           device_hint()};
    const VkFormatFeatureFlags2 color = gpu.format_features(LitPass::kColorFormat);
    if (!(color & VK_FORMAT_FEATURE_2_COLOR_ATTACHMENT_BIT))
        return Unsupported{fmt::format("device '{}' cannot render to RGBA32F", gpu.info().name), device_hint()};
    return std::nullopt;
}

std::optional<std::string> unsupported_reason(const GpuContext& gpu, const Scene& scene, const FramePlan& plan) {
    if (auto unsupported = check_supported(gpu, scene, plan)) return std::move(unsupported->reason);
    return std::nullopt;
}

FrameRenderer::FrameRenderer(const GpuContext& gpu, const Scene& scene, const std::vector<TriangleMesh>& meshes,
                             uint32_t width, uint32_t height, const FramePlan& plan)
    : gpu_(gpu),
      plan_(plan),
      background_(scene.background),
      near_plane_(scene.camera.near_plane),
      far_plane_(scene.camera.far_plane) {
    if (auto reason = unsupported_reason(gpu, scene, plan)) throw GpuError(*reason);
    scene_ = std::make_unique<GpuScene>(gpu, ledger_, scene, meshes);
    if (plan.shadow_map || plan.moment_map)
        light_view_ = compute_light_view(*scene.shadow_light(), scene_bounds(scene, meshes),
                                         plan.shadow_map ? plan.shadow_map->resolution : plan.moment_map->resolution);

    uniforms_ = Buffer(gpu, ledger_, "frame", sizeof(FrameUniforms), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    FrameUniforms u = make_uniforms(scene, width, height, plan, light_view_);
    std::memcpy(uniforms_.mapped(), &u, sizeof(u));

    create_descriptors();
    std::vector<std::string> names;
    if (plan.shadow_map) {
        shadow_pass_ = std::make_unique<ShadowMapPass>(gpu, ledger_, *plan.shadow_map, pipeline_layout_);
        names.push_back("shadow_map");
        if (!plan.shadow_map->coarse_filters.empty()) {
            const uint32_t size = plan.shadow_map->resolution;
            // The coarse passes may read the frame (e.g. the light's size).
            coarse_map_ = std::make_unique<FilterChain>(gpu, ledger_, "technique", shadow_pass_->depth().view(),
                                                        VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL, nullptr, size, size,
                                                        VK_FORMAT_R32_SFLOAT, plan.shadow_map->coarse_filters,
                                                        FilterExtras{uniforms_.handle()});
            for (size_t i = 0; i < coarse_map_->size(); ++i) names.push_back(coarse_map_->name(i));
        }
    }
    if (plan.moment_map) {
        moment_pass_ = std::make_unique<MomentMapPass>(gpu, ledger_, *plan.moment_map, pipeline_layout_);
        names.push_back("moment_map");
        for (size_t i = 0; i < moment_pass_->filter_count(); ++i) names.push_back(moment_pass_->filter_name(i));
    }
    if (plan.screen_shadow) {
        screen_pass_ = std::make_unique<ScreenShadowPass>(gpu, ledger_, width, height, *plan.screen_shadow,
                                                          pipeline_layout_, uniforms_.handle(),
                                                          shadow_pass_->depth().view());
        names.push_back("screen_shadow");
        for (size_t i = 0; i < screen_pass_->filter_count(); ++i) names.push_back(screen_pass_->filter_name(i));
    }
    lit_pass_ = std::make_unique<LitPass>(gpu, ledger_, width, height, plan.forward_fragment_spirv, pipeline_layout_);
    names.push_back("lit");
    timer_ = std::make_unique<PassTimer>(gpu, names);

    // Bind the maps the plan asked for, now that they exist.
    if (moment_pass_) bind_image(3, moment_sampler_, moment_pass_->result(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    if (coarse_map_) bind_image(4, nearest_sampler_, coarse_map_->result(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    if (screen_pass_) bind_image(5, nearest_sampler_, screen_pass_->result(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    if (shadow_pass_) {
        std::array<VkDescriptorImageInfo, 2> images{{
            {nearest_sampler_, shadow_pass_->depth().view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL},
            {compare_sampler_, shadow_pass_->depth().view(), VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL},
        }};
        std::array<VkWriteDescriptorSet, 2> writes{};
        for (uint32_t i = 0; i < 2; ++i) {
            writes[i] = {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
            writes[i].dstSet = descriptor_set_;
            writes[i].dstBinding = 1 + i;
            writes[i].descriptorCount = 1;
            writes[i].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
            writes[i].pImageInfo = &images[i];
        }
        vkUpdateDescriptorSets(gpu.device(), uint32_t(writes.size()), writes.data(), 0, nullptr);
    }

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.queueFamilyIndex = gpu.queue_family();
    VK_CHECK(vkCreateCommandPool(gpu.device(), &pool_info, nullptr, &command_pool_));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = command_pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(gpu.device(), &alloc, &commands_));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(gpu.device(), &fence_info, nullptr, &fence_));
    record();
}

FrameRenderer::~FrameRenderer() {
    VkDevice device = gpu_.device();
    vkDeviceWaitIdle(device);
    vkDestroyFence(device, fence_, nullptr);
    vkDestroyCommandPool(device, command_pool_, nullptr);
    vkDestroySampler(device, nearest_sampler_, nullptr);
    vkDestroySampler(device, compare_sampler_, nullptr);
    vkDestroySampler(device, moment_sampler_, nullptr);
    vkDestroyDescriptorPool(device, descriptor_pool_, nullptr);
    vkDestroyPipelineLayout(device, pipeline_layout_, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
}

void FrameRenderer::bind_image(uint32_t binding, VkSampler sampler, VkImageView view, VkImageLayout layout) {
    VkDescriptorImageInfo image{sampler, view, layout};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = descriptor_set_;
    write.dstBinding = binding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    write.pImageInfo = &image;
    vkUpdateDescriptorSets(gpu_.device(), 1, &write, 0, nullptr);
}

void FrameRenderer::create_descriptors() {
    VkDevice device = gpu_.device();
    const VkShaderStageFlags stages = VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT;
    // Only the bindings this plan uses: some drivers (lavapipe 22.3) read every descriptor of a
    // bound set, so a layout must not hold bindings that are never written.
    const VkShaderStageFlags fragment = VK_SHADER_STAGE_FRAGMENT_BIT;
    std::vector<VkDescriptorSetLayoutBinding> bindings{{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr}};
    auto add_sampler = [&](uint32_t binding) {
        bindings.push_back({binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, fragment, nullptr});
    };
    if (plan_.shadow_map) {
        add_sampler(1);  // depth map, NEAREST
        add_sampler(2);  // depth map, LINEAR compare
        if (!plan_.shadow_map->coarse_filters.empty()) add_sampler(4);  // coarse map
    }
    if (plan_.moment_map) add_sampler(3);     // moment map, LINEAR
    if (plan_.screen_shadow) add_sampler(5);  // screen shadow, NEAREST
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = uint32_t(bindings.size());
    set_info.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_));

    VkPushConstantRange push{stages, 0, sizeof(DrawConstants)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &pipeline_layout_));

    std::array<VkDescriptorPoolSize, 2> sizes{{{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1},
                                               {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, uint32_t(bindings.size() - 1)}}};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = bindings.size() > 1 ? 2u : 1u;  // no zero-sized pool entries
    pool_info.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &descriptor_pool_));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = descriptor_pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device, &alloc, &descriptor_set_));

    VkDescriptorBufferInfo buffer{uniforms_.handle(), 0, sizeof(FrameUniforms)};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = descriptor_set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &buffer;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);

    if (plan_.shadow_map) {
        nearest_sampler_ = create_sampler(device, VK_FILTER_NEAREST);
        compare_sampler_ = create_sampler(device, VK_FILTER_LINEAR, true);  // hardware 2x2 PCF
    }
    if (plan_.moment_map) moment_sampler_ = create_sampler(device, VK_FILTER_LINEAR);
}

void FrameRenderer::record() {
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
    timer_->reset(commands_);
    size_t slot = 0;
    if (shadow_pass_) {
        timer_->begin(commands_, slot);
        shadow_pass_->record(commands_, *scene_, pipeline_layout_, descriptor_set_);
        timer_->end(commands_, slot);
        ++slot;
        for (size_t i = 0; coarse_map_ && i < coarse_map_->size(); ++i, ++slot) {
            timer_->begin(commands_, slot);
            coarse_map_->record(commands_, i);
            timer_->end(commands_, slot);
        }
    }
    if (moment_pass_) {
        timer_->begin(commands_, slot);
        moment_pass_->record_render(commands_, *scene_, pipeline_layout_, descriptor_set_);
        timer_->end(commands_, slot);
        ++slot;
        for (size_t i = 0; i < moment_pass_->filter_count(); ++i, ++slot) {
            timer_->begin(commands_, slot);
            moment_pass_->record_filter(commands_, i);
            timer_->end(commands_, slot);
        }
    }
    if (screen_pass_) {
        timer_->begin(commands_, slot);
        screen_pass_->record_render(commands_, *scene_, pipeline_layout_, descriptor_set_);
        timer_->end(commands_, slot);
        ++slot;
        for (size_t i = 0; i < screen_pass_->filter_count(); ++i, ++slot) {
            timer_->begin(commands_, slot);
            screen_pass_->record_filter(commands_, i);
            timer_->end(commands_, slot);
        }
    }
    timer_->begin(commands_, slot);
    lit_pass_->record(commands_, *scene_, pipeline_layout_, descriptor_set_, background_);
    timer_->end(commands_, slot);
    VK_CHECK(vkEndCommandBuffer(commands_));
}

FrameTiming FrameRenderer::render() {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    const auto start = std::chrono::steady_clock::now();
    VK_CHECK(vkQueueSubmit(gpu_.queue(), 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(gpu_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    const auto stop = std::chrono::steady_clock::now();
    VK_CHECK(vkResetFences(gpu_.device(), 1, &fence_));

    FrameTiming timing;
    timing.wall_ms = std::chrono::duration<double, std::milli>(stop - start).count();
    timing.pass_gpu_ms = timer_->read_milliseconds();
    timing.gpu_ms = timing.pass_gpu_ms.back();
    timing.pass_gpu_ms.pop_back();
    return timing;
}

namespace {

// Copies the whole of `texture` (in `layout`, left in it) into host memory, 4 bytes per texel
// for depth, 16 for RGBA32F.
std::vector<float> read_texels(const GpuContext& gpu, const Texture& texture, VkImageLayout layout, size_t channels) {
    const size_t count = size_t(texture.width()) * texture.height() * channels;
    MemoryLedger readback_ledger;  // transient, not charged to the technique
    Buffer staging(gpu, readback_ledger, "readback", count * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    VkCommandBuffer commands = gpu.begin_commands();
    const bool move = layout != VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    if (move) transition(commands, texture, layout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);
    VkBufferImageCopy region{};
    region.imageSubresource = {texture.aspect(), 0, 0, 1};
    region.imageExtent = {texture.width(), texture.height(), 1};
    vkCmdCopyImageToBuffer(commands, texture.image(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    if (move) transition(commands, texture, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, layout);
    gpu.submit_and_wait(commands);
    std::vector<float> texels(count);
    std::memcpy(texels.data(), staging.mapped(), count * sizeof(float));
    return texels;
}

}  // namespace

namespace {

// The colour target's texels as the image users see: alpha holds the technique's visibility
// (read_pixel_visibility), the image is opaque.
Image opaque_color(const Texture& color, std::vector<float> rgba) {
    Image image(int(color.width()), int(color.height()));
    image.pixels = std::move(rgba);
    for (size_t i = 3; i < image.pixels.size(); i += 4) image.pixels[i] = 1.0f;
    return image;
}

// Stored depth is glm::perspective's (zero to one): z = f (d - n) / ((f - n) d) for view depth d,
// so d = f n / (f - z (f - n)); the clear value 1 (the far plane) means nothing was drawn.
Image pixel_visibility_image(const Texture& color, const std::vector<float>& rgba, const std::vector<float>& depth,
                             double n, double f) {
    namespace pv = pixel_visibility;
    Image image(int(color.width()), int(color.height()));
    for (size_t i = 0; i < depth.size(); ++i) {
        float* p = &image.pixels[4 * i];
        const bool drawn = depth[i] < 1.0f;
        p[pv::kVisibility] = rgba[4 * i + 3];
        p[pv::kViewDepth] = drawn ? float(f * n / (f - double(depth[i]) * (f - n))) : 0.0f;
        p[pv::kSurface] = drawn ? 1.0f : 0.0f;
    }
    return image;
}

}  // namespace

Image FrameRenderer::read_color() const {
    const Texture& color = lit_pass_->color();
    return opaque_color(color, read_texels(gpu_, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 4));
}

Image FrameRenderer::read_pixel_visibility() const { return read_color_and_pixel_visibility().visibility; }

FrameRenderer::ColorAndVisibility FrameRenderer::read_color_and_pixel_visibility() const {
    const Texture& color = lit_pass_->color();
    std::vector<float> rgba = read_texels(gpu_, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, 4);
    const std::vector<float> depth = read_texels(gpu_, lit_pass_->depth(), VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL, 1);
    Image visibility = pixel_visibility_image(color, rgba, depth, near_plane_, far_plane_);
    return {opaque_color(color, std::move(rgba)), std::move(visibility)};
}

Image FrameRenderer::read_coarse_map() const {
    if (!coarse_map_) throw std::logic_error("read_coarse_map: the plan has no coarse map");
    return read_texture(gpu_, coarse_map_->result_texture(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

Image FrameRenderer::read_screen_shadow() const {
    if (!screen_pass_) throw std::logic_error("read_screen_shadow: the plan has no screen-shadow pass");
    return read_texture(gpu_, screen_pass_->result_texture(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

MemoryUse FrameRenderer::memory() const {
    return {ledger_.bytes("technique"), ledger_.bytes("targets"), ledger_.bytes("scene")};
}

std::string FrameRenderer::shadow_sampler() const {
    if (plan_.moment_map) return std::string("linear-") + to_string(plan_.moment_map->format);
    if (!plan_.shadow_map) return "";
    return plan_.shadow_map->compare_sampler ? "compare-linear" : "nearest";
}

}  // namespace canopy
