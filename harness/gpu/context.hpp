// The Vulkan instance, the chosen device and its one graphics queue.
#pragma once

#include "gpu/vk_check.hpp"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace canopy {

struct DeviceInfo {
    int index = 0;
    std::string name;          // "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string type;          // "cpu", "discrete-gpu", "integrated-gpu", "virtual-gpu", "other"
    std::string driver_name;   // "llvmpipe", "NVIDIA"
    std::string driver_info;   // "Mesa 22.3.6 (LLVM 15.0.6)"
    std::string api_version;   // "1.3.230"
    uint32_t vendor_id = 0, device_id = 0;
    bool is_lavapipe() const { return type == "cpu"; }
};

// Every warning and error the Vulkan validation layers report through the context's debug-utils
// messenger, from instance creation to destruction (objects left alive are reported when the
// device and instance are destroyed, so keep the log past the context to see those).
class ValidationLog {
public:
    void add(const std::string& message);
    std::vector<std::string> messages() const;
    size_t count() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

class GpuContext {
public:
    // from_environment: the validation layers run when CANOPY_VALIDATION is set (and not "0");
    // on: they run regardless. Either way a missing layer is a GpuError naming the package.
    enum class Validation { from_environment, on };

    // Every Vulkan device on this machine. Throws GpuError when Vulkan itself is unavailable.
    static std::vector<DeviceInfo> list_devices();

    // `selector` is "" (lavapipe if present, else the first device), an index from `canopy
    // devices`, or a case-insensitive substring of a device name. Unknown selectors throw
    // ConfigError listing the devices. Needs Vulkan 1.3 (dynamic rendering, synchronization2).
    explicit GpuContext(const std::string& selector = "", Validation validation = Validation::from_environment);
    ~GpuContext();
    GpuContext(const GpuContext&) = delete;
    GpuContext& operator=(const GpuContext&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical_device() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    const DeviceInfo& info() const { return info_; }
    // What the validation layers said so far; null when they are not running.
    std::shared_ptr<const ValidationLog> validation_log() const { return validation_log_; }
    double timestamp_period_ns() const { return timestamp_period_ns_; }
    uint32_t timestamp_valid_bits() const { return timestamp_valid_bits_; }
    bool storage_write_without_format() const { return storage_write_without_format_; }
    bool draw_indirect_count() const { return draw_indirect_count_; }
    bool pipeline_statistics() const { return pipeline_statistics_; }  // primitive counts (PrimitiveCounter)
    bool alpha_to_one() const { return alpha_to_one_; }  // alpha-to-coverage pipelines store alpha 1
    bool sample_rate_shading() const { return sample_rate_shading_; }  // fragment shaders may run per sample
    // What SamplerKind::anisotropic samplers take: up to 16, 1 where the device has no samplerAnisotropy.
    float max_anisotropy() const { return max_anisotropy_; }

    uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const;
    VkFormatFeatureFlags2 format_features(VkFormat format) const;  // optimal tiling

    // One-shot command buffers for uploads and readbacks.
    VkCommandBuffer begin_commands() const;
    void submit_and_wait(VkCommandBuffer commands) const;  // frees the buffer

private:
    VkInstance instance_ = VK_NULL_HANDLE;
    std::shared_ptr<ValidationLog> validation_log_;  // outlives the instance: it hears its destruction
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkFence fence_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    DeviceInfo info_;
    double timestamp_period_ns_ = 1.0;
    uint32_t timestamp_valid_bits_ = 0;
    bool storage_write_without_format_ = false;
    bool draw_indirect_count_ = false;
    bool pipeline_statistics_ = false;
    bool alpha_to_one_ = false;
    bool sample_rate_shading_ = false;
    float max_anisotropy_ = 1.0f;
    VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace canopy
