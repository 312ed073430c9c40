#include "render/filter_chain.hpp"

#include "gpu/rendering.hpp"

#include <algorithm>
#include <array>

namespace canopy {

namespace {

struct FilterPushConstants {
    int32_t direction[2];
    int32_t radius;
    int32_t downsample;
    int32_t extent[2];      // output
    int32_t src_extent[2];  // input
};

}  // namespace

FilterChain::FilterChain(const GpuContext& gpu, MemoryLedger& ledger, const std::string& category, VkImageView source,
                         VkImageLayout source_layout, Texture* writable_source, uint32_t width, uint32_t height,
                         VkFormat format, std::vector<FilterPass> passes, const FilterExtras& extras)
    : gpu_(gpu), passes_(std::move(passes)), writable_source_(writable_source) {
    if (passes_.empty()) return;
    extents_.push_back({width, height});
    for (const FilterPass& pass : passes_) {
        const uint32_t f = uint32_t(std::max(pass.downsample, 1));
        per_pass_images_ = per_pass_images_ || f > 1;
        // Rounded up: a partial block at the edge still gets its own output texel.
        extents_.push_back({std::max((extents_.back().width + f - 1) / f, 1u), std::max((extents_.back().height + f - 1) / f, 1u)});
    }
    const VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;  // + readback
    if (per_pass_images_) {
        writable_source_ = nullptr;
        for (size_t i = 0; i < passes_.size(); ++i)
            images_.emplace_back(gpu, ledger, category, extents_[i + 1].width, extents_[i + 1].height, format, usage,
                                 VK_IMAGE_ASPECT_COLOR_BIT);
    } else {
        images_.emplace_back(gpu, ledger, category, width, height, format, usage, VK_IMAGE_ASPECT_COLOR_BIT);
        if (passes_.size() > 1 && !writable_source)
            images_.emplace_back(gpu, ledger, category, width, height, format, usage, VK_IMAGE_ASPECT_COLOR_BIT);
    }

    VkDevice device = gpu.device();
    nearest_ = create_sampler(device, VK_FILTER_NEAREST);

    const VkShaderStageFlags stage = VK_SHADER_STAGE_COMPUTE_BIT;
    // Only the bindings this chain is given (see FrameRenderer::create_descriptors for why).
    std::vector<VkDescriptorSetLayoutBinding> bindings{
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, stage, nullptr},
    };
    if (extras.frame_uniforms) bindings.push_back({2, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stage, nullptr});
    if (extras.shadow_depth) bindings.push_back({3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr});
    if (extras.aux) bindings.push_back({4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, stage, nullptr});
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = uint32_t(bindings.size());
    set_info.pBindings = bindings.data();
    VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_));
    VkPushConstantRange push{stage, 0, sizeof(FilterPushConstants)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &push;
    VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout_));

    const uint32_t n = uint32_t(passes_.size());
    std::array<VkDescriptorPoolSize, 3> sizes{{{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 3 * n},
                                               {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, n},
                                               {VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, n}}};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = n;
    pool_info.poolSizeCount = uint32_t(sizes.size());
    pool_info.pPoolSizes = sizes.data();
    VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool_));
    std::vector<VkDescriptorSetLayout> layouts(n, set_layout_);
    sets_.resize(n);
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = n;
    alloc.pSetLayouts = layouts.data();
    VK_CHECK(vkAllocateDescriptorSets(device, &alloc, sets_.data()));

    for (size_t i = 0; i < passes_.size(); ++i) {
        const VkImageView read_view = i == 0 ? source : output(i - 1).view();
        const VkImageLayout read_layout = i == 0 ? source_layout : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        VkDescriptorImageInfo read{nearest_, read_view, read_layout};
        VkDescriptorImageInfo write{VK_NULL_HANDLE, output(i).view(), VK_IMAGE_LAYOUT_GENERAL};
        VkDescriptorBufferInfo frame{extras.frame_uniforms, 0, VK_WHOLE_SIZE};
        VkDescriptorImageInfo depth{nearest_, extras.shadow_depth, VK_IMAGE_LAYOUT_DEPTH_READ_ONLY_OPTIMAL};
        VkDescriptorImageInfo aux{nearest_, extras.aux, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        std::vector<VkWriteDescriptorSet> writes;
        auto image_write = [&](uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo* info) {
            writes.push_back({VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, sets_[i], binding, 0, 1, type, info, nullptr, nullptr});
        };
        image_write(0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &read);
        image_write(1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, &write);
        if (extras.frame_uniforms)
            writes.push_back({VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, sets_[i], 2, 0, 1,
                              VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, nullptr, &frame, nullptr});
        if (extras.shadow_depth) image_write(3, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &depth);
        if (extras.aux) image_write(4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, &aux);
        vkUpdateDescriptorSets(device, uint32_t(writes.size()), writes.data(), 0, nullptr);
        pipelines_.push_back(std::make_unique<ComputePipeline>(gpu, passes_[i].compute_spirv, layout_));
    }
}

FilterChain::~FilterChain() {
    VkDevice device = gpu_.device();
    pipelines_.clear();
    if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
    if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
    if (set_layout_) vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
    if (nearest_) vkDestroySampler(device, nearest_, nullptr);
}

const Texture& FilterChain::output(size_t index) const {
    if (per_pass_images_) return images_[index];
    if (index % 2 == 0) return images_[0];
    return writable_source_ ? *writable_source_ : images_[1];
}

void FilterChain::record(VkCommandBuffer commands, size_t index) const {
    const FilterPass& pass = passes_[index];
    const Texture& destination = output(index);
    transition(commands, destination, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL);
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_COMPUTE, pipelines_[index]->handle());
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &sets_[index], 0, nullptr);
    const VkExtent2D in = extents_[index], out = extents_[index + 1];
    FilterPushConstants push{{pass.horizontal ? 1 : 0, pass.horizontal ? 0 : 1}, pass.radius, std::max(pass.downsample, 1),
                             {int32_t(out.width), int32_t(out.height)}, {int32_t(in.width), int32_t(in.height)}};
    vkCmdPushConstants(commands, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(push), &push);
    vkCmdDispatch(commands, (out.width + 7) / 8, (out.height + 7) / 8, 1);
    transition(commands, destination, VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

VkImageView FilterChain::result() const { return output(passes_.size() - 1).view(); }

const Texture& FilterChain::result_texture() const { return output(passes_.size() - 1); }

}  // namespace canopy
