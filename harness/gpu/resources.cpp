#include "gpu/resources.hpp"

#include <cstring>
#include <utility>

namespace canopy {

VkDeviceMemory allocate_memory(const GpuContext& gpu, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = gpu.memory_type(req.memoryTypeBits, flags);
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(gpu.device(), &info, nullptr, &memory));
    return memory;
}

Buffer::Buffer(const GpuContext& gpu, MemoryLedger& ledger, std::string category, VkDeviceSize size,
               VkBufferUsageFlags usage, bool host_visible)
    : gpu_(&gpu), ledger_(&ledger), category_(std::move(category)), size_(size) {
    VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    info.size = size;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VK_CHECK(vkCreateBuffer(gpu.device(), &info, nullptr, &buffer_));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(gpu.device(), buffer_, &req);
    memory_ = allocate_memory(gpu, req,
                       host_visible ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
                                    : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    allocated_ = req.size;
    ledger_->add(category_, allocated_);
    VK_CHECK(vkBindBufferMemory(gpu.device(), buffer_, memory_, 0));
    if (host_visible) VK_CHECK(vkMapMemory(gpu.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
}

Buffer& Buffer::operator=(Buffer&& other) noexcept {
    if (this != &other) {
        release();
        gpu_ = std::exchange(other.gpu_, nullptr);
        ledger_ = std::exchange(other.ledger_, nullptr);
        category_ = std::move(other.category_);
        buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        size_ = std::exchange(other.size_, 0);
        allocated_ = std::exchange(other.allocated_, 0);
        mapped_ = std::exchange(other.mapped_, nullptr);
    }
    return *this;
}

Buffer::~Buffer() { release(); }

void Buffer::release() {
    if (!gpu_) return;
    if (mapped_) vkUnmapMemory(gpu_->device(), memory_);
    vkDestroyBuffer(gpu_->device(), buffer_, nullptr);
    vkFreeMemory(gpu_->device(), memory_, nullptr);
    ledger_->remove(category_, allocated_);
    gpu_ = nullptr;
}

Buffer upload_buffer(const GpuContext& gpu, MemoryLedger& ledger, const std::string& category, const void* bytes,
                     size_t size, VkBufferUsageFlags usage) {
    MemoryLedger staging_ledger;  // staging memory is transient, not charged to anyone
    Buffer staging(gpu, staging_ledger, "staging", size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    std::memcpy(staging.mapped(), bytes, size);
    Buffer buffer(gpu, ledger, category, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
    VkCommandBuffer commands = gpu.begin_commands();
    VkBufferCopy region{0, 0, size};
    vkCmdCopyBuffer(commands, staging.handle(), buffer.handle(), 1, &region);
    gpu.submit_and_wait(commands);
    return buffer;
}

}  // namespace canopy
