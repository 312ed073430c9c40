// GPU buffers and images with their memory, owned RAII-style. Each allocation is charged to a
// MemoryLedger category so results can report memory per technique.
#pragma once

#include "gpu/context.hpp"

#include <cstddef>
#include <map>
#include <string>

namespace canopy {

// Bytes of device memory allocated per category ("scene", "technique", "targets").
class MemoryLedger {
public:
    void add(const std::string& category, VkDeviceSize bytes) { bytes_[category] += bytes; }
    void remove(const std::string& category, VkDeviceSize bytes) { bytes_[category] -= bytes; }
    VkDeviceSize bytes(const std::string& category) const {
        auto it = bytes_.find(category);
        return it == bytes_.end() ? 0 : it->second;
    }
    const std::map<std::string, VkDeviceSize>& all() const { return bytes_; }

private:
    std::map<std::string, VkDeviceSize> bytes_;
};

class Buffer {
public:
    Buffer() = default;
    // Host-visible buffers stay mapped (mapped() != nullptr).
    Buffer(const GpuContext& gpu, MemoryLedger& ledger, std::string category, VkDeviceSize size,
           VkBufferUsageFlags usage, bool host_visible);
    ~Buffer();
    Buffer(Buffer&& other) noexcept { *this = std::move(other); }
    Buffer& operator=(Buffer&& other) noexcept;

    VkBuffer handle() const { return buffer_; }
    VkDeviceSize size() const { return size_; }
    void* mapped() const { return mapped_; }

private:
    void release();
    const GpuContext* gpu_ = nullptr;
    MemoryLedger* ledger_ = nullptr;
    std::string category_;
    VkBuffer buffer_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0, allocated_ = 0;
    void* mapped_ = nullptr;
};

class Texture {
public:
    Texture() = default;
    Texture(const GpuContext& gpu, MemoryLedger& ledger, std::string category, uint32_t width, uint32_t height,
            VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect);
    ~Texture();
    Texture(Texture&& other) noexcept { *this = std::move(other); }
    Texture& operator=(Texture&& other) noexcept;

    VkImage image() const { return image_; }
    VkImageView view() const { return view_; }
    VkFormat format() const { return format_; }
    VkImageAspectFlags aspect() const { return aspect_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

private:
    void release();
    const GpuContext* gpu_ = nullptr;
    MemoryLedger* ledger_ = nullptr;
    std::string category_;
    VkImage image_ = VK_NULL_HANDLE;
    VkImageView view_ = VK_NULL_HANDLE;
    VkDeviceMemory memory_ = VK_NULL_HANDLE;
    VkDeviceSize allocated_ = 0;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkImageAspectFlags aspect_ = 0;
    uint32_t width_ = 0, height_ = 0;
};

// Uploads `bytes` into a new device-local buffer through a staging copy.
Buffer upload_buffer(const GpuContext& gpu, MemoryLedger& ledger, const std::string& category, const void* bytes,
                     size_t size, VkBufferUsageFlags usage);

// Layout transition as a synchronization2 barrier covering all commands on both sides.
void transition(VkCommandBuffer commands, const Texture& texture, VkImageLayout from, VkImageLayout to);

}  // namespace canopy
