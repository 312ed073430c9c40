#include "graph/graph_resources.hpp"

#include <fmt/format.h>

#include <set>

#include <stdexcept>

namespace canopy {

namespace {

bool is_depth(VkFormat format) {
    return format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D32_SFLOAT || format == VK_FORMAT_X8_D24_UNORM_PACK32;
}

VkImageUsageFlags image_usage(const FrameGraph& graph, const ImageDecl& decl) {
    const std::string& name = decl.name;
    VkImageUsageFlags usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // readbacks for tests and images
    // The executor clears persistent images to zeros before their first use (vkCmdClear*Image).
    if (decl.persistent) usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    for (const PassDecl& p : graph.passes)
        for (const ResourceUse& u : p.uses) {
            if (u.resource != name) continue;
            switch (u.use) {
                case Use::sampled: usage |= VK_IMAGE_USAGE_SAMPLED_BIT; break;
                case Use::storage_read:
                case Use::storage_write: usage |= VK_IMAGE_USAGE_STORAGE_BIT; break;
                case Use::color_attachment:
                case Use::resolve_target: usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT; break;
                case Use::depth_attachment: usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT; break;
                case Use::transfer_write: usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT; break;
                default: break;
            }
        }
    return usage;
}

VkBufferUsageFlags buffer_usage(const BufferDecl& decl) {
    VkBufferUsageFlags usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;
    if (decl.usage & kVertexBuffer) usage |= VK_BUFFER_USAGE_VERTEX_BUFFER_BIT;
    if (decl.usage & kIndexBuffer) usage |= VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
    if (decl.usage & kStorageBuffer) usage |= VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
    if (decl.usage & kIndirectBuffer) usage |= VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT;
    if (decl.usage & kUniformBuffer) usage |= VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT;
    return usage;
}

VkSampleCountFlagBits sample_bits(uint32_t samples) { return VkSampleCountFlagBits(samples); }

}  // namespace

GraphImage::GraphImage(const GpuContext& gpu, MemoryLedger& ledger, std::string category, const ImageDecl& decl,
                       uint32_t width, uint32_t height, VkImageUsageFlags usage)
    : gpu_(gpu), ledger_(ledger), category_(std::move(category)), decl_(decl), width_(width), height_(height),
      aspect_(is_depth(decl.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT),
      layouts_(size_t(decl.mips) * decl.layers, VK_IMAGE_LAYOUT_UNDEFINED) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = decl.format;
    info.extent = {width, height, 1};
    info.mipLevels = decl.mips;
    info.arrayLayers = decl.layers;
    info.samples = sample_bits(decl.samples);
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(gpu.device(), &info, nullptr, &image_));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(gpu.device(), image_, &req);
    memory_ = allocate_memory(gpu, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    allocated_ = req.size;
    ledger_.add(category_, allocated_);
    VK_CHECK(vkBindImageMemory(gpu.device(), image_, memory_, 0));
}

GraphImage::~GraphImage() {
    for (auto& [key, view] : views_) vkDestroyImageView(gpu_.device(), view, nullptr);
    vkDestroyImage(gpu_.device(), image_, nullptr);
    vkFreeMemory(gpu_.device(), memory_, nullptr);
    ledger_.remove(category_, allocated_);
}

Subresource GraphImage::clamp(const Subresource& range) const {
    Subresource r = range;
    r.mip_count = std::min(r.mip_count, decl_.mips - std::min(r.mip, decl_.mips));
    r.layer_count = std::min(r.layer_count, decl_.layers - std::min(r.layer, decl_.layers));
    if (r.mip_count == 0 || r.layer_count == 0)
        throw std::logic_error(fmt::format("image '{}': mips {}+ / layers {}+ lie outside its {} mips and {} layers",
                                           decl_.name, range.mip, range.layer, decl_.mips, decl_.layers));
    return r;
}

VkImageView GraphImage::view(const Subresource& range) {
    const Subresource r = clamp(range);
    const std::array<uint32_t, 4> key{r.mip, r.mip_count, r.layer, r.layer_count};
    if (auto it = views_.find(key); it != views_.end()) return it->second;
    VkImageViewCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    info.image = image_;
    // Layered images always get array views (one layer of them included), so shaders see one type;
    // so do images declared arrayed.
    info.viewType = decl_.layers > 1 || decl_.arrayed ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
    info.format = decl_.format;
    info.subresourceRange = {aspect_, r.mip, r.mip_count, r.layer, r.layer_count};
    VkImageView view;
    VK_CHECK(vkCreateImageView(gpu_.device(), &info, nullptr, &view));
    views_.emplace(key, view);
    return view;
}

void GraphImage::forget_contents() {
    for (VkImageLayout& l : layouts_) l = VK_IMAGE_LAYOUT_UNDEFINED;
}

GraphResources::GraphResources(const GpuContext& gpu, MemoryLedger& ledger, const FrameGraph& graph, uint32_t width,
                               uint32_t height, const Buffer& frame_uniforms, uint64_t copies, bool on_terrain)
    : frame_uniforms_(&frame_uniforms) {
    const auto add_image = [&](const ImageDecl& decl, const std::string& category) {
        uint32_t w = decl.extent.width, h = decl.extent.height;
        if (decl.extent.rule == ImageExtent::Rule::screen) {
            w = (width + decl.extent.divisor - 1) / decl.extent.divisor;
            h = (height + decl.extent.divisor - 1) / decl.extent.divisor;
        }
        images_.emplace(decl.name, std::make_unique<GraphImage>(gpu, ledger, category, decl, w, h,
                                                                image_usage(graph, decl)));
    };
    add_image(ImageDecl{graph_names::kColor, kColorTargetFormat, ImageExtent::screen()}, "targets");
    add_image(ImageDecl{graph_names::kDepth, kDepthTargetFormat, ImageExtent::screen()}, "targets");
    for (const ImageDecl& decl : graph.images) add_image(decl, "technique");
    for (const BufferDecl& decl : graph.buffers) {
        // Vulkan has no empty buffers: a per-copy buffer of a scene without copies gets 16 bytes,
        // as does a terrain's buffer without one.
        uint64_t bytes = decl.only_on_terrain && !on_terrain ? 0 : decl.bytes + decl.bytes_per_copy * copies;
        if (bytes == 0) bytes = 16;
        buffers_.emplace(decl.name, Buffer(gpu, ledger, "technique", bytes, buffer_usage(decl), decl.host_visible));
        host_visible_[decl.name] = decl.host_visible;
        if (decl.host_visible) std::memset(buffers_.at(decl.name).mapped(), 0, bytes);
    }
}

namespace {

std::string missing(const char* what, const std::string& name, const std::set<std::string>& released) {
    if (released.count(name))
        return fmt::format("the frame graph's {} '{}' was released after the load phase: no frame pass uses it and it "
                           "is not persistent (declare it persistent to keep it)",
                           what, name);
    return fmt::format("the frame graph has no {} '{}'", what, name);
}

}  // namespace

GraphImage& GraphResources::image(const std::string& name) const {
    auto it = images_.find(name);
    if (it == images_.end()) throw std::logic_error(missing("image", name, released_));
    return *it->second;
}

const Buffer& GraphResources::buffer(const std::string& name) const {
    if (name == graph_names::kFrameUniforms) return *frame_uniforms_;
    auto it = buffers_.find(name);
    if (it == buffers_.end()) throw std::logic_error(missing("buffer", name, released_));
    return it->second;
}

void GraphResources::release(const std::string& name) {
    if (images_.erase(name) + buffers_.erase(name) > 0) released_.insert(name);
    host_visible_.erase(name);
}

bool GraphResources::host_visible(const std::string& name) const {
    auto it = host_visible_.find(name);
    return it != host_visible_.end() && it->second;
}

void GraphResources::begin_frame() {
    for (auto& [name, image] : images_)
        if (!image->decl().persistent) image->forget_contents();
}

}  // namespace canopy
