#include "run/test_ballast.hpp"

#include "gpu/vk_check.hpp"
#include "shaders/harness/test_ballast_comp.h"

#include <cstdlib>
#include <stdexcept>

namespace canopy {

namespace {

struct WorkConstants {
    uint32_t iterations;
    uint32_t count;
};

}  // namespace

std::optional<BallastSpec> ballast_from_environment() {
    const char* value = std::getenv("CANOPY_TEST_BALLAST");
    if (!value || !*value) return std::nullopt;
    const std::string text = value;
    const size_t equals = text.rfind('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == text.size())
        throw std::invalid_argument("CANOPY_TEST_BALLAST must be <technique>=<iterations>, got '" + text + "'");
    char* end = nullptr;
    const unsigned long iterations = std::strtoul(text.c_str() + equals + 1, &end, 10);
    if (*end != '\0' || iterations == 0 || iterations > 1000000)
        throw std::invalid_argument("CANOPY_TEST_BALLAST's iterations must lie in [1, 1000000], got '" + text + "'");
    return BallastSpec{text.substr(0, equals), uint32_t(iterations)};
}

Ballast::Ballast(const GpuContext& gpu, uint32_t width, uint32_t height, uint32_t iterations)
    : gpu_(gpu),
      count_(width * height),
      iterations_(iterations),
      sink_(gpu, ledger_, "ballast", VkDeviceSize(width) * height * sizeof(uint32_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            false) {
    VkDevice device = gpu.device();
    VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr};
    VkDescriptorSetLayoutCreateInfo set_info{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    set_info.bindingCount = 1;
    set_info.pBindings = &binding;
    VK_CHECK(vkCreateDescriptorSetLayout(device, &set_info, nullptr, &set_layout_));
    VkPushConstantRange constants{VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof(WorkConstants)};
    VkPipelineLayoutCreateInfo layout_info{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    layout_info.setLayoutCount = 1;
    layout_info.pSetLayouts = &set_layout_;
    layout_info.pushConstantRangeCount = 1;
    layout_info.pPushConstantRanges = &constants;
    VK_CHECK(vkCreatePipelineLayout(device, &layout_info, nullptr, &layout_));
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
    VkDescriptorPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pool_info.maxSets = 1;
    pool_info.poolSizeCount = 1;
    pool_info.pPoolSizes = &size;
    VK_CHECK(vkCreateDescriptorPool(device, &pool_info, nullptr, &pool_));
    VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    alloc.descriptorPool = pool_;
    alloc.descriptorSetCount = 1;
    alloc.pSetLayouts = &set_layout_;
    VK_CHECK(vkAllocateDescriptorSets(device, &alloc, &set_));
    VkDescriptorBufferInfo buffer{sink_.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstSet = set_;
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &buffer;
    vkUpdateDescriptorSets(device, 1, &write, 0, nullptr);
    pipeline_ = std::make_unique<ComputePipeline>(gpu, test_ballast_comp, layout_);
    timer_ = std::make_unique<PassTimer>(gpu, std::vector<std::string>{"test_ballast"});

    VkCommandPoolCreateInfo command_pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    command_pool_info.queueFamilyIndex = gpu.queue_family();
    VK_CHECK(vkCreateCommandPool(device, &command_pool_info, nullptr, &command_pool_));
    VkCommandBufferAllocateInfo command_alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    command_alloc.commandPool = command_pool_;
    command_alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    command_alloc.commandBufferCount = 1;
    VK_CHECK(vkAllocateCommandBuffers(device, &command_alloc, &commands_));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device, &fence_info, nullptr, &fence_));

    // A barrier on both sides of the dispatch, inside the timed span: lavapipe writes a timestamp
    // only when its pending work is flushed, and a barrier flushes it (the filter passes' layout
    // transitions do the same), so the first stamp is taken before the dispatch runs and the
    // second after it.
    VkMemoryBarrier2 storage{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    storage.srcStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    storage.srcAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    storage.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    storage.dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.memoryBarrierCount = 1;
    dependency.pMemoryBarriers = &storage;

    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    VK_CHECK(vkBeginCommandBuffer(commands_, &begin));
    timer_->reset(commands_);
    timer_->begin(commands_, 0);
    vkCmdPipelineBarrier2(commands_, &dependency);
    vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_->handle());
    vkCmdBindDescriptorSets(commands_, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0, 1, &set_, 0, nullptr);
    const WorkConstants work{iterations_, count_};
    vkCmdPushConstants(commands_, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof work, &work);
    vkCmdDispatch(commands_, (count_ + 63) / 64, 1, 1);
    vkCmdPipelineBarrier2(commands_, &dependency);
    timer_->end(commands_, 0);
    VK_CHECK(vkEndCommandBuffer(commands_));
}

Ballast::~Ballast() {
    VkDevice device = gpu_.device();
    vkDeviceWaitIdle(device);
    vkDestroyFence(device, fence_, nullptr);
    vkDestroyCommandPool(device, command_pool_, nullptr);
    pipeline_.reset();
    vkDestroyDescriptorPool(device, pool_, nullptr);
    vkDestroyPipelineLayout(device, layout_, nullptr);
    vkDestroyDescriptorSetLayout(device, set_layout_, nullptr);
}

double Ballast::run_ms() {
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands_;
    VK_CHECK(vkQueueSubmit(gpu_.queue(), 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(gpu_.device(), 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(gpu_.device(), 1, &fence_));
    return timer_->read_milliseconds().back();
}

}  // namespace canopy
