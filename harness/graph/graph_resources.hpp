// The images and buffers of one frame graph, allocated as declared, with the Vulkan usage each
// needs derived from how the passes use it. Tracks every image subresource's layout, so the
// executor can derive the barriers a use needs.
#pragma once

#include "gpu/resources.hpp"
#include "graph/frame_graph.hpp"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace canopy {

class GraphImage {
public:
    GraphImage(const GpuContext& gpu, MemoryLedger& ledger, std::string category, const ImageDecl& decl,
               uint32_t width, uint32_t height, VkImageUsageFlags usage);
    ~GraphImage();
    GraphImage(const GraphImage&) = delete;
    GraphImage& operator=(const GraphImage&) = delete;

    const ImageDecl& decl() const { return decl_; }
    VkImage image() const { return image_; }
    VkFormat format() const { return decl_.format; }
    VkImageAspectFlags aspect() const { return aspect_; }
    uint32_t width(uint32_t mip = 0) const { return std::max(width_ >> mip, 1u); }
    uint32_t height(uint32_t mip = 0) const { return std::max(height_ >> mip, 1u); }
    // The range with ~0 counts replaced by what remains of the image.
    Subresource clamp(const Subresource& range) const;
    // A view of `range` (created once): 2D for one layer, 2D array for several.
    VkImageView view(const Subresource& range);
    // Layout of (mip, layer) as the commands recorded so far leave it.
    VkImageLayout& layout(uint32_t mip, uint32_t layer) { return layouts_[mip * decl_.layers + layer]; }
    void forget_contents();  // every subresource UNDEFINED (a transient image at a frame's start)

private:
    const GpuContext& gpu_;
    MemoryLedger& ledger_;
    std::string category_;
    ImageDecl decl_;
    uint32_t width_, height_;
    VkImageAspectFlags aspect_;
    VkImage image_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize allocated_ = 0;
    std::map<std::array<uint32_t, 4>, VkImageView> views_;
    std::vector<VkImageLayout> layouts_;
};

class GraphResources {
public:
    // Allocates `graph`'s images and buffers, plus the harness's camera targets (color, depth:
    // charged to "targets") at width x height; technique resources are charged to "technique".
    // `copies`: how many copies the scene's populations of the graph's kinds hold
    // (BufferDecl::bytes_per_copy); `on_terrain`: whether one stands on a terrain
    // (BufferDecl::only_on_terrain).
    GraphResources(const GpuContext& gpu, MemoryLedger& ledger, const FrameGraph& graph, uint32_t width, uint32_t height,
                   const Buffer& frame_uniforms, uint64_t copies = 0, bool on_terrain = false);

    GraphImage& image(const std::string& name) const;
    bool has_image(const std::string& name) const { return images_.count(name) != 0; }
    const Buffer& buffer(const std::string& name) const;
    bool host_visible(const std::string& name) const;
    VkDeviceSize buffer_bytes(const std::string& name) const { return buffer(name).size(); }
    const std::map<std::string, std::unique_ptr<GraphImage>>& images() const { return images_; }
    // Transient images' contents are undefined at a frame's start.
    void begin_frame();
    // Frees a resource no pass will use again (the executor's, after the load phase); naming it
    // afterwards is an error that says so.
    void release(const std::string& name);

private:
    std::map<std::string, std::unique_ptr<GraphImage>> images_;
    std::map<std::string, Buffer> buffers_;
    std::map<std::string, bool> host_visible_;
    std::set<std::string> released_;
    const Buffer* frame_uniforms_;
};

// The camera targets every graph renders into.
inline constexpr VkFormat kColorTargetFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthTargetFormat = VK_FORMAT_D32_SFLOAT;

}  // namespace canopy
