// GPU buffers with their memory, owned RAII-style (frame-graph images: graph/graph_resources.hpp). Each allocation is charged to a
// MemoryLedger category so results can report memory per technique.
#pragma once

#include "gpu/context.hpp"

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>

namespace canopy {

// Bytes of device memory allocated per category ("scene", "technique", "targets").
class MemoryLedger {
public:
    void add(const std::string& category, VkDeviceSize bytes) {
        VkDeviceSize& held = bytes_[category];
        held += bytes;
        VkDeviceSize& peak = peaks_[category];
        peak = std::max(peak, held);
    }
    void remove(const std::string& category, VkDeviceSize bytes) { bytes_[category] -= bytes; }
    VkDeviceSize bytes(const std::string& category) const {
        auto it = bytes_.find(category);
        return it == bytes_.end() ? 0 : it->second;
    }
    // The most `category` has held at once (a frame graph's load phase holds resources it then releases).
    VkDeviceSize peak(const std::string& category) const {
        auto it = peaks_.find(category);
        return it == peaks_.end() ? 0 : it->second;
    }
    const std::map<std::string, VkDeviceSize>& all() const { return bytes_; }

private:
    std::map<std::string, VkDeviceSize> bytes_;
    std::map<std::string, VkDeviceSize> peaks_;
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

// Uploads `bytes` into a new device-local buffer through a staging copy.
Buffer upload_buffer(const GpuContext& gpu, MemoryLedger& ledger, const std::string& category, const void* bytes,
                     size_t size, VkBufferUsageFlags usage);

// Device memory of `flags` for `requirements`, from the first fitting memory type.
VkDeviceMemory allocate_memory(const GpuContext& gpu, const VkMemoryRequirements& requirements, VkMemoryPropertyFlags flags);

}  // namespace canopy
