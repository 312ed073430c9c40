// A chain of compute passes (FilterPass) over a 2D image: pass 0 reads the source, each later
// pass reads the previous output. Same-size outputs ping-pong between two images; a chain with
// a downsampling pass gets one image per pass instead (of ceil(input / downsample) texels: a
// partial block at the edge gets its own texel). Used for moment-map prefilters, the
// coarse (downsampled, min-filtered) shadow map and screen-space blurs.
#pragma once

#include "core/technique.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/resources.hpp"

#include <memory>
#include <vector>

namespace canopy {

// What every filter shader may read besides its source (see separable_filter.glsl).
struct FilterExtras {
    VkBuffer frame_uniforms = VK_NULL_HANDLE;  // binding 2: the frame uniform block
    VkImageView shadow_depth = VK_NULL_HANDLE; // binding 3: the depth shadow map (NEAREST), DEPTH_READ_ONLY
    VkImageView aux = VK_NULL_HANDLE;          // binding 4: an auxiliary image (NEAREST), SHADER_READ_ONLY
};

class FilterChain {
public:
    // `source` must be in `source_layout` whenever the chain runs. When `writable_source` is
    // given (the source itself, with STORAGE usage), later passes write back into it and the
    // chain allocates one image instead of two.
    FilterChain(const GpuContext& gpu, MemoryLedger& ledger, const std::string& category, VkImageView source,
                VkImageLayout source_layout, Texture* writable_source, uint32_t width, uint32_t height, VkFormat format,
                std::vector<FilterPass> passes, const FilterExtras& extras = {});
    ~FilterChain();
    FilterChain(const FilterChain&) = delete;
    FilterChain& operator=(const FilterChain&) = delete;

    size_t size() const { return passes_.size(); }
    const std::string& name(size_t index) const { return passes_[index].name; }
    void record(VkCommandBuffer commands, size_t index) const;  // leaves its output SHADER_READ_ONLY
    VkImageView result() const;                                  // the last pass's output
    const Texture& result_texture() const;                       // the same, for readbacks

private:
    const Texture& output(size_t index) const;

    const GpuContext& gpu_;
    std::vector<FilterPass> passes_;
    std::vector<VkExtent2D> extents_;  // input extent of pass i is extents_[i], output extents_[i + 1]
    Texture* writable_source_;
    std::vector<Texture> images_;      // two (ping-pong) or one per pass (downsampling chains)
    bool per_pass_images_ = false;
    VkSampler nearest_ = VK_NULL_HANDLE;
    VkDescriptorSetLayout set_layout_ = VK_NULL_HANDLE;
    VkPipelineLayout layout_ = VK_NULL_HANDLE;
    VkDescriptorPool pool_ = VK_NULL_HANDLE;
    std::vector<VkDescriptorSet> sets_;  // one per pass
    std::vector<std::unique_ptr<ComputePipeline>> pipelines_;
};

}  // namespace canopy
