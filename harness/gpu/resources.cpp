#include "gpu/resources.hpp"

#include <cstring>
#include <utility>

namespace canopy {

namespace {

VkDeviceMemory allocate(const GpuContext& gpu, const VkMemoryRequirements& req, VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo info{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    info.allocationSize = req.size;
    info.memoryTypeIndex = gpu.memory_type(req.memoryTypeBits, flags);
    VkDeviceMemory memory;
    VK_CHECK(vkAllocateMemory(gpu.device(), &info, nullptr, &memory));
    return memory;
}

}  // namespace

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
    memory_ = allocate(gpu, req,
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

Texture::Texture(const GpuContext& gpu, MemoryLedger& ledger, std::string category, uint32_t width,
                 uint32_t height, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect)
    : gpu_(&gpu), ledger_(&ledger), category_(std::move(category)), format_(format), aspect_(aspect),
      width_(width), height_(height) {
    VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {width, height, 1};
    info.mipLevels = 1;
    info.arrayLayers = 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VK_CHECK(vkCreateImage(gpu.device(), &info, nullptr, &image_));
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(gpu.device(), image_, &req);
    memory_ = allocate(gpu, req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    allocated_ = req.size;
    ledger_->add(category_, allocated_);
    VK_CHECK(vkBindImageMemory(gpu.device(), image_, memory_, 0));

    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image_;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format;
    view.subresourceRange = {aspect, 0, 1, 0, 1};
    VK_CHECK(vkCreateImageView(gpu.device(), &view, nullptr, &view_));
}

Texture& Texture::operator=(Texture&& other) noexcept {
    if (this != &other) {
        release();
        gpu_ = std::exchange(other.gpu_, nullptr);
        ledger_ = std::exchange(other.ledger_, nullptr);
        category_ = std::move(other.category_);
        image_ = std::exchange(other.image_, VK_NULL_HANDLE);
        view_ = std::exchange(other.view_, VK_NULL_HANDLE);
        memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
        allocated_ = std::exchange(other.allocated_, 0);
        format_ = other.format_;
        aspect_ = other.aspect_;
        width_ = other.width_;
        height_ = other.height_;
    }
    return *this;
}

Texture::~Texture() { release(); }

void Texture::release() {
    if (!gpu_) return;
    vkDestroyImageView(gpu_->device(), view_, nullptr);
    vkDestroyImage(gpu_->device(), image_, nullptr);
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

void transition(VkCommandBuffer commands, const Texture& texture, VkImageLayout from, VkImageLayout to) {
    VkImageMemoryBarrier2 barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    barrier.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
    barrier.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = texture.image();
    barrier.subresourceRange = {texture.aspect(), 0, 1, 0, 1};
    VkDependencyInfo dependency{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dependency.imageMemoryBarrierCount = 1;
    dependency.pImageMemoryBarriers = &barrier;
    vkCmdPipelineBarrier2(commands, &dependency);
}

}  // namespace canopy
