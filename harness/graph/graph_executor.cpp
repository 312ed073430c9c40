#include "graph/graph_executor.hpp"

#include "graph/pass_context.hpp"
#include "gpu/samplers.hpp"
#include "render/frame_uniforms.hpp"
#include "render/gpu_scene.hpp"
#include "scene/camera.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <map>
#include <set>
#include <stdexcept>

namespace canopy {

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point start) { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); }

bool is_buffer_resource(const GraphResources& r, const std::string& name) { return !r.has_image(name); }

VkShaderStageFlags stages_of(PassKind kind) {
    return kind == PassKind::compute ? VkShaderStageFlags(VK_SHADER_STAGE_COMPUTE_BIT)
                                     : VkShaderStageFlags(VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT);
}

// The layout an image subresource must be in for `use`.
VkImageLayout layout_for(Use use, VkImageAspectFlags aspect) {
    const bool depth = aspect & VK_IMAGE_ASPECT_DEPTH_BIT;
    switch (use) {
        case Use::sampled: return depth ? VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        case Use::storage_read:
        case Use::storage_write: return VK_IMAGE_LAYOUT_GENERAL;
        case Use::color_attachment:
        case Use::resolve_target: return VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        case Use::depth_attachment: return VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
        case Use::transfer_read: return VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
        case Use::transfer_write: return VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
        default: return VK_IMAGE_LAYOUT_UNDEFINED;
    }
}

VkMemoryBarrier2 memory_barrier(VkPipelineStageFlags2 src_stages, VkAccessFlags2 src_access, VkPipelineStageFlags2 dst_stages,
                                VkAccessFlags2 dst_access) {
    VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    b.srcStageMask = src_stages;
    b.srcAccessMask = src_access;
    b.dstStageMask = dst_stages;
    b.dstAccessMask = dst_access;
    return b;
}

VkImageMemoryBarrier2 image_barrier(const GraphImage& image, uint32_t mip, uint32_t layer, VkImageLayout from,
                                    VkImageLayout to) {
    // Whole-pipeline dependencies, as the renderer always had: a pass's work is a few draws or
    // dispatches, and finer stages would save nothing measurable on lavapipe.
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image.image();
    b.subresourceRange = {image.aspect(), mip, 1, layer, 1};
    return b;
}

}  // namespace

// A pass's descriptor set (its declared descriptor uses) and pipeline layout.
struct GraphExecutor::PassBinding {
    VkDescriptorSetLayout set_layout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkDescriptorSet set = VK_NULL_HANDLE;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    AttachmentFormats targets;
    VkShaderStageFlags push_stages = 0;
};

// What one pass records with: the services of PassContext over this executor's resources.
class GraphExecutor::Context final : public PassContext, public CpuPassContext {
public:
    Context(GraphExecutor& executor, VkCommandBuffer commands, const FrameState& state)
        : ex_(executor), commands_(commands), state_(state) {}

    void start_pass(size_t index) { pass_ = index; }
    // Draw commands pass `index` recorded this frame (FrameTiming::pass_draws).
    uint32_t draws(size_t index) const {
        const auto it = draws_.find(index);
        return it == draws_.end() ? 0 : it->second;
    }
    uint64_t uploaded_bytes() const { return uploaded_; }
    const std::vector<std::pair<std::string, double>>& counters() const { return counters_; }

    const FrameState& frame() const override { return state_; }
    glm::mat4 view_proj() const override { return view_projection(state_.camera, ex_.width_, ex_.height_); }
    void count(const std::string& name, double value) override {
        for (auto& [n, v] : counters_)
            if (n == name) {
                v += value;
                return;
            }
        counters_.emplace_back(name, value);
    }

    VkPipeline raster_pipeline(const RasterState& state) override {
        const PassBinding& b = binding();
        return ex_.pipelines_->raster(state, b.targets, b.layout);
    }
    VkPipeline compute_pipeline(std::span<const uint32_t> spirv) override {
        return ex_.pipelines_->compute(spirv, binding().layout);
    }
    void bind(VkPipeline pipeline) override {
        vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    }
    void draw_scene(SceneFilter filter) override {
        note_draw();
        ex_.scene_.draw(commands_, binding().layout, filter == SceneFilter::shadow_casters);
    }
    std::span<const GeneratedPopulation> populations() const override { return ex_.scene_.populations(); }
    void draw_population(const std::string& name, uint32_t max_copies) override {
        note_draw();
        ex_.scene_.draw_population(commands_, binding().layout, name, max_copies);
    }
    VkDrawIndexedIndirectCommand population_draw_arguments(const std::string& name) const override {
        return ex_.scene_.draw_arguments(name);
    }
    void draw_population_indirect(const std::string& name, const std::string& copies,
                                  const std::string& arguments) override {
        note_draw();
        ex_.scene_.draw_population_indirect(commands_, binding().layout, name, ex_.resources_->buffer(copies).handle(),
                                            ex_.resources_->buffer(arguments).handle());
    }
    void draw_prototype(const std::string& name, uint32_t instances) override {
        note_draw();
        ex_.scene_.draw_prototype(commands_, binding().layout, name, instances);
    }
    void draw_over_population(const std::string& name, std::span<const std::string> vertex_buffers,
                              uint32_t vertex_count) override {
        note_draw();
        std::vector<VkBuffer> buffers;
        for (const std::string& b : vertex_buffers) buffers.push_back(ex_.resources_->buffer(b).handle());
        ex_.scene_.draw_over_population(commands_, binding().layout, name, buffers, vertex_count);
    }
    void draw_over_population_indirect(const std::string& name, std::span<const std::string> vertex_buffers,
                                       const std::string& copies, const std::string& arguments) override {
        note_draw();
        std::vector<VkBuffer> buffers;
        for (const std::string& b : vertex_buffers) buffers.push_back(ex_.resources_->buffer(b).handle());
        ex_.scene_.draw_over_population_indirect(commands_, binding().layout, name, buffers,
                                                 ex_.resources_->buffer(copies).handle(),
                                                 ex_.resources_->buffer(arguments).handle());
    }
    void draw(std::span<const std::string> vertex_buffers, uint32_t vertex_count, uint32_t instance_count) override {
        note_draw();
        bind_vertex_buffers(vertex_buffers);
        vkCmdDraw(commands_, vertex_count, instance_count, 0, 0);
    }
    void draw_indexed(std::span<const std::string> vertex_buffers, const std::string& index_buffer, uint32_t index_count,
                      uint32_t instance_count) override {
        note_draw();
        bind_vertex_buffers(vertex_buffers);
        vkCmdBindIndexBuffer(commands_, ex_.resources_->buffer(index_buffer).handle(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexed(commands_, index_count, instance_count, 0, 0, 0);
    }
    void draw_indirect(std::span<const std::string> vertex_buffers, const std::string& arguments) override {
        note_draw();
        bind_vertex_buffers(vertex_buffers);
        vkCmdDrawIndirect(commands_, ex_.resources_->buffer(arguments).handle(), 0, 1, sizeof(VkDrawIndirectCommand));
    }
    void draw_indexed_indirect_count(std::span<const std::string> vertex_buffers, const std::string& index_buffer,
                                     const std::string& arguments, const std::string& count, uint32_t max_draws) override {
        if (!ex_.gpu_.draw_indirect_count())
            throw GpuError(fmt::format("device '{}' lacks drawIndirectCount (pass '{}')", ex_.gpu_.info().name, pass().name));
        note_draw();
        bind_vertex_buffers(vertex_buffers);
        vkCmdBindIndexBuffer(commands_, ex_.resources_->buffer(index_buffer).handle(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexedIndirectCount(commands_, ex_.resources_->buffer(arguments).handle(), 0,
                                      ex_.resources_->buffer(count).handle(), 0, max_draws,
                                      sizeof(VkDrawIndexedIndirectCommand));
    }
    void push_constants(const void* bytes, uint32_t size) override {
        if (size > pass().push_constant_bytes)
            throw std::logic_error(fmt::format("pass '{}' pushes {} bytes but declares {}", pass().name, size,
                                               pass().push_constant_bytes));
        vkCmdPushConstants(commands_, binding().layout, binding().push_stages, 0, size, bytes);
    }
    void dispatch(VkPipeline pipeline, uint32_t x, uint32_t y, uint32_t z) override {
        vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
        vkCmdDispatch(commands_, x, y, z);
    }
    void fill(const std::string& buffer, uint32_t value) override {
        vkCmdFillBuffer(commands_, ex_.resources_->buffer(buffer).handle(), 0, VK_WHOLE_SIZE, value);
        after_transfer();
    }
    void upload(const std::string& buffer, const void* bytes, size_t size, size_t offset) override {
        const Buffer& target = ex_.resources_->buffer(buffer);
        if (offset + size > target.size())
            throw std::logic_error(fmt::format("pass '{}' uploads {} bytes at {} into '{}' of {} bytes", pass().name, size,
                                               offset, buffer, target.size()));
        uploaded_ += size;
        if (target.mapped()) {
            std::memcpy(static_cast<std::byte*>(target.mapped()) + offset, bytes, size);
            return;
        }
        if (pass().kind == PassKind::cpu)
            throw std::logic_error(fmt::format("CPU pass '{}' uploads into '{}', which is not host_visible", pass().name, buffer));
        staging_.emplace_back(ex_.gpu_, staging_ledger_, "staging", size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        std::memcpy(staging_.back().mapped(), bytes, size);
        VkBufferCopy region{0, offset, size};
        vkCmdCopyBuffer(commands_, staging_.back().handle(), target.handle(), 1, &region);
        after_transfer();
    }
    void copy_buffer(const std::string& from, const std::string& to) override {
        const Buffer& a = ex_.resources_->buffer(from);
        const Buffer& b = ex_.resources_->buffer(to);
        VkBufferCopy region{0, 0, std::min(a.size(), b.size())};
        vkCmdCopyBuffer(commands_, a.handle(), b.handle(), 1, &region);
        after_transfer();
    }
    void upload_image(const std::string& name, const void* bytes, size_t size, uint32_t mip, uint32_t layer) override {
        GraphImage& image = ex_.resources_->image(name);
        uploaded_ += size;
        staging_.emplace_back(ex_.gpu_, staging_ledger_, "staging", size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        std::memcpy(staging_.back().mapped(), bytes, size);
        VkBufferImageCopy region{};
        region.imageSubresource = {image.aspect(), mip, layer, 1};
        region.imageExtent = {image.width(mip), image.height(mip), 1};
        vkCmdCopyBufferToImage(commands_, staging_.back().handle(), image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                               &region);
        after_transfer();
    }
    VkExtent2D extent(const std::string& image) const override {
        const GraphImage& i = ex_.resources_->image(image);
        return {i.width(), i.height()};
    }
    VkCommandBuffer raw_commands() override { return commands_; }
    std::span<const std::byte> read(const std::string& buffer) const override {
        const Buffer& b = ex_.resources_->buffer(buffer);
        if (!b.mapped()) throw std::logic_error(fmt::format("buffer '{}' is not host_visible: a CPU pass cannot read it", buffer));
        return {static_cast<const std::byte*>(b.mapped()), size_t(b.size())};
    }

    // Staging memory lives until the submission completes, charged to no one (declared before
    // the buffers it outlives).
    MemoryLedger staging_ledger_;
    std::vector<Buffer> staging_;

private:
    const PassDecl& pass() const { return ex_.graph_.passes[pass_]; }
    // A transfer inside a compute pass (a reset before its dispatch) must land before the pass's
    // shaders run: the executor's derived barriers come only between passes. A copy pass needs
    // none (the next pass's barrier covers it).
    void after_transfer() {
        if (pass().kind != PassKind::compute) return;
        const VkMemoryBarrier2 memory =
            memory_barrier(VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        dependency.memoryBarrierCount = 1;
        dependency.pMemoryBarriers = &memory;
        vkCmdPipelineBarrier2(commands_, &dependency);
    }
    const PassBinding& binding() const { return *ex_.bindings_[pass_]; }
    void bind_vertex_buffers(std::span<const std::string> names) {
        for (uint32_t i = 0; i < names.size(); ++i) {
            VkBuffer handle = ex_.resources_->buffer(names[i]).handle();
            VkDeviceSize offset = 0;
            vkCmdBindVertexBuffers(commands_, i, 1, &handle, &offset);
        }
    }

    GraphExecutor& ex_;
    VkCommandBuffer commands_;
    const FrameState& state_;
    size_t pass_ = 0;
    uint64_t uploaded_ = 0;
    std::vector<std::pair<std::string, double>> counters_;
    std::map<size_t, uint32_t> draws_;  // per pass index
    void note_draw() { ++draws_[pass_]; }
};

GraphExecutor::GraphExecutor(const GpuContext& gpu, MemoryLedger& ledger, FrameGraph graph, uint32_t width,
                             uint32_t height, const Buffer& frame_uniforms, const GpuScene& scene)
    : gpu_(gpu), graph_(std::move(graph)), scene_(scene), width_(width), height_(height) {
    if (std::string problem = validate(graph_); !problem.empty())
        throw std::logic_error("malformed frame graph: " + problem);
    uint64_t copies = 0;
    bool on_terrain = false;
    for (const GeneratedPopulation& population : scene.populations()) {
        copies += population.instances.size();
        on_terrain = on_terrain || population.on_terrain;
    }
    resources_ = std::make_unique<GraphResources>(gpu, ledger, graph_, width, height, frame_uniforms, copies, on_terrain);
    pipelines_ = std::make_unique<PipelineCache>(gpu);
    for (size_t i = 0; i < graph_.passes.size(); ++i) {
        const PassDecl& p = graph_.passes[i];
        PhasePasses& phase = phases_[int(p.phase)];
        phase.passes.push_back(i);
        (p.kind == PassKind::cpu ? phase.cpu_names : phase.gpu_names).push_back(p.name);
    }
    for (PhasePasses& phase : phases_)
        if (!phase.gpu_names.empty()) phase.timer = std::make_unique<PassTimer>(gpu, phase.gpu_names);
    create_pass_bindings();

    // Nothing a pass reads is ever uninitialised: device buffers start as zeros, persistent images
    // as zeros (transient images are always written before they are read: validate()).
    VkCommandBuffer commands = gpu.begin_commands();
    for (const BufferDecl& b : graph_.buffers)
        if (!b.host_visible) vkCmdFillBuffer(commands, resources_->buffer(b.name).handle(), 0, VK_WHOLE_SIZE, 0);
    for (const ImageDecl& decl : graph_.images) {
        if (!decl.persistent) continue;
        GraphImage& image = resources_->image(decl.name);
        transition(commands, image, {}, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL);
        const VkImageSubresourceRange all{image.aspect(), 0, decl.mips, 0, decl.layers};
        if (image.aspect() & VK_IMAGE_ASPECT_DEPTH_BIT) {
            VkClearDepthStencilValue zero{};
            vkCmdClearDepthStencilImage(commands, image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &all);
        } else {
            VkClearColorValue zero{};
            vkCmdClearColorImage(commands, image.image(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &all);
        }
    }
    gpu.submit_and_wait(commands);

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = gpu.queue_family();
    VK_CHECK(vkCreateCommandPool(gpu.device(), &pool_info, nullptr, &command_pool_));
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = command_pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(gpu.device(), &alloc, &commands_));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(gpu.device(), &fence_info, nullptr, &fence_));
}

GraphExecutor::~GraphExecutor() {
    VkDevice device = gpu_.device();
    vkDeviceWaitIdle(device);
    vkDestroyFence(device, fence_, nullptr);
    vkDestroyCommandPool(device, command_pool_, nullptr);
    for (auto& b : bindings_) {
        if (b->pool) vkDestroyDescriptorPool(device, b->pool, nullptr);
        vkDestroyPipelineLayout(device, b->layout, nullptr);
        if (b->set_layout) vkDestroyDescriptorSetLayout(device, b->set_layout, nullptr);
    }
    for (VkSampler s : samplers_)
        if (s) vkDestroySampler(device, s, nullptr);
}

VkSampler GraphExecutor::sampler(SamplerKind kind) {
    VkSampler& s = samplers_[size_t(kind)];
    if (s) return s;
    VkDevice device = gpu_.device();
    switch (kind) {
        case SamplerKind::nearest: s = create_sampler(device, VK_FILTER_NEAREST); break;
        case SamplerKind::linear: s = create_sampler(device, VK_FILTER_LINEAR); break;
        case SamplerKind::compare_linear: s = create_sampler(device, VK_FILTER_LINEAR, true); break;
        case SamplerKind::linear_mipmap:
        case SamplerKind::anisotropic: {
            VkSamplerCreateInfo info{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
            info.magFilter = info.minFilter = VK_FILTER_LINEAR;
            info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
            info.addressModeU = info.addressModeV = info.addressModeW = VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
            info.maxLod = VK_LOD_CLAMP_NONE;
            if (kind == SamplerKind::anisotropic && gpu_.max_anisotropy() > 1.0f) {
                info.anisotropyEnable = VK_TRUE;
                info.maxAnisotropy = gpu_.max_anisotropy();
            }
            VK_CHECK(vkCreateSampler(device, &info, nullptr, &s));
            break;
        }
    }
    return s;
}

void GraphExecutor::create_pass_bindings() {
    VkDevice device = gpu_.device();
    for (const PassDecl& p : graph_.passes) {
        auto b = std::make_unique<PassBinding>();
        const VkShaderStageFlags stages = stages_of(p.kind);
        std::vector<VkDescriptorSetLayoutBinding> layout_bindings;
        std::vector<VkDescriptorPoolSize> sizes;
        struct Write {
            uint32_t binding;
            VkDescriptorType type;
            VkDescriptorImageInfo image{};
            VkDescriptorBufferInfo buffer{};
        };
        std::vector<Write> writes;
        for (const ResourceUse& u : p.uses) {
            if (u.use == Use::color_attachment || u.use == Use::depth_attachment) {
                const GraphImage& image = resources_->image(u.resource);
                if (u.use == Use::color_attachment) b->targets.colors.push_back(image.format());
                else b->targets.depth = image.format();
                b->targets.samples = image.decl().samples;
            }
            if (u.binding < 0 || p.kind == PassKind::cpu) continue;
            Write w{uint32_t(u.binding), VK_DESCRIPTOR_TYPE_MAX_ENUM};
            if (u.use == Use::uniform) {
                w.type = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
                w.buffer = {resources_->buffer(u.resource).handle(), 0, VK_WHOLE_SIZE};
            } else if (is_buffer_resource(*resources_, u.resource)) {
                w.type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                w.buffer = {resources_->buffer(u.resource).handle(), 0, VK_WHOLE_SIZE};
            } else {
                GraphImage& image = resources_->image(u.resource);
                const VkImageView view = image.view(u.range);
                if (u.use == Use::sampled) {
                    w.type = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
                    w.image = {sampler(u.sampler), view, layout_for(Use::sampled, image.aspect())};
                } else {
                    w.type = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
                    w.image = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
                }
            }
            writes.push_back(w);
            layout_bindings.push_back({w.binding, w.type, 1, stages, nullptr});
            sizes.push_back({w.type, 1});
        }
        // Only the bindings the pass uses: some drivers (lavapipe 22.3) read every descriptor of
        // a bound set, so a layout must not hold bindings that are never written.
        if (!layout_bindings.empty()) {
            VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
            set_info.bindingCount = uint32_t(layout_bindings.size());
            set_info.pBindings = layout_bindings.data();
            VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &b->set_layout));
            VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
            pool_info.maxSets = 1;
            pool_info.poolSizeCount = uint32_t(sizes.size());
            pool_info.pPoolSizes = sizes.data();
            VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &b->pool));
            VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
            alloc.descriptorPool = b->pool;
            alloc.descriptorSetCount = 1;
            alloc.pSetLayouts = &b->set_layout;
            VK_CHECK(vkAllocateDescriptorSets(device, &alloc, &b->set));
            std::vector<VkWriteDescriptorSet> vk_writes;
            for (const Write& w : writes) {
                VkWriteDescriptorSet v{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
                v.dstSet = b->set;
                v.dstBinding = w.binding;
                v.descriptorCount = 1;
                v.descriptorType = w.type;
                const bool buffer = w.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER || w.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
                v.pBufferInfo = buffer ? &w.buffer : nullptr;
                v.pImageInfo = buffer ? nullptr : &w.image;
                vk_writes.push_back(v);
            }
            vkUpdateDescriptorSets(device, uint32_t(vk_writes.size()), vk_writes.data(), 0, nullptr);
        }
        b->push_stages = stages;
        VkPushConstantRange push{stages, 0, p.push_constant_bytes};
        VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
        layout_info.setLayoutCount = b->set_layout ? 1u : 0u;
        layout_info.pSetLayouts = &b->set_layout;
        layout_info.pushConstantRangeCount = p.push_constant_bytes ? 1u : 0u;
        layout_info.pPushConstantRanges = &push;
        VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &b->layout));
        bindings_.push_back(std::move(b));
    }
}

void GraphExecutor::transition(VkCommandBuffer commands, GraphImage& image, const Subresource& range,
                               VkImageLayout layout) {
    const Subresource r = image.clamp(range);
    std::vector<VkImageMemoryBarrier2> barriers;
    for (uint32_t m = r.mip; m < r.mip + r.mip_count; ++m)
        for (uint32_t l = r.layer; l < r.layer + r.layer_count; ++l) {
            VkImageLayout& current = image.layout(m, l);
            barriers.push_back(image_barrier(image, m, l, current, layout));
            current = layout;
        }
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = uint32_t(barriers.size());
    dependency.pImageMemoryBarriers = barriers.data();
    vkCmdPipelineBarrier2(commands, &dependency);
}

void GraphExecutor::barriers_for(VkCommandBuffer commands, const PassDecl& pass) {
    // Images: a barrier per subresource whose layout changes, or that an earlier pass wrote, or
    // that this pass writes (a write after any access). Buffers: one memory barrier when this pass
    // touches a buffer an earlier pass wrote since the last one, or writes any buffer.
    std::vector<VkImageMemoryBarrier2> image_barriers;
    bool buffer_barrier = false;
    for (const ResourceUse& u : pass.uses) {
        if (!resources_->has_image(u.resource)) {
            if (buffer_written_[u.resource] || u.writes() || u.use == Use::storage_write) buffer_barrier = true;
            continue;
        }
        GraphImage& image = *resources_->images().at(u.resource);
        const Subresource r = image.clamp(u.range);
        const VkImageLayout target = layout_for(u.use, image.aspect());
        for (uint32_t m = r.mip; m < r.mip + r.mip_count; ++m)
            for (uint32_t l = r.layer; l < r.layer + r.layer_count; ++l) {
                VkImageLayout& current = image.layout(m, l);
                const bool written_before = current == VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL ||
                                            current == VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL ||
                                            current == VK_IMAGE_LAYOUT_GENERAL || current == VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
                if (current != target || written_before || u.writes()) {
                    // Contents an attachment clears or a transient image never held need no layout kept.
                    image_barriers.push_back(image_barrier(image, m, l, current, target));
                    current = target;
                }
            }
    }
    if (buffer_barrier) buffer_written_.clear();
    for (const ResourceUse& u : pass.uses)
        if (!resources_->has_image(u.resource) && (u.writes() || u.use == Use::storage_write))
            buffer_written_[u.resource] = true;
    if (image_barriers.empty() && !buffer_barrier) return;
    const VkMemoryBarrier2 memory =
        memory_barrier(VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                       VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = buffer_barrier ? 1u : 0u;
    dependency.pMemoryBarriers = &memory;
    dependency.imageMemoryBarrierCount = uint32_t(image_barriers.size());
    dependency.pImageMemoryBarriers = image_barriers.data();
    vkCmdPipelineBarrier2(commands, &dependency);
}

void GraphExecutor::record_pass(VkCommandBuffer commands, size_t index, Context& context) {
    const PassDecl& p = graph_.passes[index];
    const PassBinding& b = *bindings_[index];
    barriers_for(commands, p);
    context.start_pass(index);
    const VkPipelineBindPoint point =
        p.kind == PassKind::compute ? VK_PIPELINE_BIND_POINT_COMPUTE : VK_PIPELINE_BIND_POINT_GRAPHICS;
    if (b.set && p.kind != PassKind::copy) vkCmdBindDescriptorSets(commands, point, b.layout, 0, 1, &b.set, 0, nullptr);
    if (p.kind != PassKind::raster) {
        p.record(context);
        return;
    }
    // Dynamic rendering into the declared attachments, in their declared order.
    std::vector<VkRenderingAttachmentInfo> colors;
    VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    bool has_depth = false;
    VkExtent2D extent{0, 0};
    size_t resolves = 0;
    for (const ResourceUse& u : p.uses) {
        if (u.use != Use::color_attachment && u.use != Use::depth_attachment && u.use != Use::resolve_target) continue;
        GraphImage& image = resources_->image(u.resource);
        const Subresource r = image.clamp(u.range);
        if (extent.width == 0) extent = {image.width(r.mip), image.height(r.mip)};
        VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
        a.imageView = image.view(u.range);
        a.loadOp = u.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        if (u.use == Use::color_attachment) {
            a.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            if (u.clear)
                for (int c = 0; c < 4; ++c) a.clearValue.color.float32[c] = (*u.clear)[size_t(c)];
            colors.push_back(a);
        } else if (u.use == Use::depth_attachment) {
            a.imageLayout = VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL;
            a.storeOp = u.store ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
            if (u.clear) a.clearValue.depthStencil = {(*u.clear)[0], 0};
            depth = a;
            has_depth = true;
        } else {  // the resolve target of the resolves-th colour attachment
            if (resolves >= colors.size())
                throw std::logic_error(fmt::format("pass '{}': resolve target '{}' precedes its colour attachment", p.name,
                                                   u.resource));
            colors[resolves].resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
            colors[resolves].resolveImageView = a.imageView;
            colors[resolves].resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            ++resolves;
        }
    }
    VkRenderingInfo rendering{VK_STRUCTURE_TYPE_RENDERING_INFO};
    rendering.renderArea = {{0, 0}, extent};
    rendering.layerCount = 1;
    rendering.colorAttachmentCount = uint32_t(colors.size());
    rendering.pColorAttachments = colors.data();
    rendering.pDepthAttachment = has_depth ? &depth : nullptr;
    vkCmdBeginRendering(commands, &rendering);
    VkViewport viewport{0.0f, 0.0f, float(extent.width), float(extent.height), 0.0f, 1.0f};
    VkRect2D scissor{{0, 0}, extent};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    vkCmdSetScissor(commands, 0, 1, &scissor);
    p.record(context);
    vkCmdEndRendering(commands);
}

PhaseTiming GraphExecutor::run(Phase phase_id, const FrameState& state, bool count_primitives) {
    PhasePasses& phase = phases_[int(phase_id)];
    PhaseTiming timing;
    const auto record_start = Clock::now();
    double cpu_total = 0;
    if (phase_id == Phase::frame) resources_->begin_frame();
    VK_CHECK(vkResetCommandBuffer(commands_, 0));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
    Context context(*this, commands_, state);
    if (phase.timer) phase.timer->reset(commands_);
    const bool counting = count_primitives && gpu_.pipeline_statistics();
    if (counting) {
        if (!primitive_counter_) primitive_counter_ = std::make_unique<PrimitiveCounter>(gpu_);
        primitive_counter_->begin(commands_);
    }
    size_t slot = 0;
    for (size_t index : phase.passes) {
        const PassDecl& p = graph_.passes[index];
        if (p.kind == PassKind::cpu) {
            context.start_pass(index);
            const auto start = Clock::now();
            p.run(context);
            timing.pass_cpu_ms.push_back(ms_since(start));
            cpu_total += timing.pass_cpu_ms.back();
            continue;
        }
        phase.timer->begin(commands_, slot);
        record_pass(commands_, index, context);
        phase.timer->end(commands_, slot);
        timing.pass_draws.push_back(context.draws(index));
        ++slot;
    }
    if (counting) primitive_counter_->end(commands_);
    VK_CHECK(vkEndCommandBuffer(commands_));
    timing.record_cpu_ms = ms_since(record_start) - cpu_total;

    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    const auto start = Clock::now();
    VK_CHECK(vkQueueSubmit(gpu_.queue(), 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(gpu_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    timing.wall_ms = ms_since(start);
    VK_CHECK(vkResetFences(gpu_.device(), 1, &fence_));
    if (phase.timer) {
        timing.pass_gpu_ms = phase.timer->read_milliseconds();
        timing.gpu_ms = timing.pass_gpu_ms.back();
        timing.pass_gpu_ms.pop_back();
    }
    timing.uploaded_bytes = context.uploaded_bytes();
    timing.counters = context.counters();
    if (counting) timing.primitives = primitive_counter_->read();
    return timing;
}

PhaseTiming GraphExecutor::run_load(const FrameState& state) {
    PhaseTiming timing = run(Phase::load, state, false);
    // What only the load phase used (a bake's depth target, a shadowed bake's light views) is
    // freed once it has run (run() waited for it): the frames then hold only what they use, and
    // the memory a case reports is theirs (MemoryLedger::peak keeps the load's).
    std::set<std::string> used_by_frames;
    for (const PassDecl& pass : graph_.passes)
        if (pass.phase == Phase::frame)
            for (const ResourceUse& use : pass.uses) used_by_frames.insert(use.resource);
    for (const ImageDecl& image : graph_.images)
        if (!image.persistent && !used_by_frames.count(image.name)) resources_->release(image.name);
    for (const BufferDecl& buffer : graph_.buffers)
        if (!buffer.persistent && !used_by_frames.count(buffer.name)) resources_->release(buffer.name);
    return timing;
}
PhaseTiming GraphExecutor::run_frame(const FrameState& state, bool count_primitives) {
    return run(Phase::frame, state, count_primitives);
}

}  // namespace canopy
