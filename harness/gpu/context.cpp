#include "gpu/context.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <cstring>
#include <iostream>

namespace canopy {

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

std::string type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_CPU: return "cpu";
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete-gpu";
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated-gpu";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual-gpu";
        default: return "other";
    }
}

std::string version_string(uint32_t v) {
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v), VK_API_VERSION_PATCH(v));
}

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool validation_requested() {
    const char* v = std::getenv("CANOPY_VALIDATION");
    return v && std::strcmp(v, "0") != 0 && *v;
}

void require_validation_layer() {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    for (const VkLayerProperties& layer : layers)
        if (std::strcmp(layer.layerName, kValidationLayer) == 0) return;
    throw GpuError(fmt::format("the Vulkan validation layer {} is not installed: install the Debian package "
                               "vulkan-validationlayers (scripts/install-deps lists it)",
                               kValidationLayer));
}

VKAPI_ATTR VkBool32 VKAPI_CALL on_validation_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data, void* log) {
    const std::string message = fmt::format(
        "{}: {}", severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "error" : "warning",
        data->pMessage ? data->pMessage : "(no message)");
    std::cerr << "vulkan validation " << message << "\n";
    static_cast<ValidationLog*>(log)->add(message);
    return VK_FALSE;
}

// Warnings and errors of every kind, delivered to `log`.
VkDebugUtilsMessengerCreateInfoEXT messenger_info(ValidationLog* log) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = on_validation_message;
    info.pUserData = log;
    return info;
}

// `log` non-null: with the validation layer, and a messenger that also hears vkCreateInstance
// and vkDestroyInstance (chained into the create info).
VkInstance create_instance(ValidationLog* log) {
    const bool validation = log != nullptr;
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "canopy";
    app.applicationVersion = VK_MAKE_VERSION(0, 1, 0);
    app.pEngineName = "canopy";
    app.apiVersion = VK_API_VERSION_1_3;

    std::vector<const char*> layers, extensions;
    if (validation) {
        layers.push_back("VK_LAYER_KHRONOS_validation");
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    }
    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    const VkDebugUtilsMessengerCreateInfoEXT instance_messenger = messenger_info(log);
    if (validation) info.pNext = &instance_messenger;
    VkInstance instance = VK_NULL_HANDLE;
    VkResult result = vkCreateInstance(&info, nullptr, &instance);
    if (result != VK_SUCCESS)
        throw GpuError(fmt::format("cannot create a Vulkan 1.3 instance ({}): is a Vulkan driver installed? "
                                   "Run scripts/install-deps (mesa-vulkan-drivers provides lavapipe){}",
                                   vk_result_name(result), validation ? "; the validation layer was enabled" : ""));
    return instance;
}

std::vector<VkPhysicalDevice> physical_devices(VkInstance instance) {
    uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> devices(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, devices.data()));
    return devices;
}

DeviceInfo describe(VkPhysicalDevice device, int index) {
    VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
    props.pNext = &driver;
    vkGetPhysicalDeviceProperties2(device, &props);
    DeviceInfo info;
    info.index = index;
    info.name = props.properties.deviceName;
    info.type = type_name(props.properties.deviceType);
    info.driver_name = driver.driverName;
    info.driver_info = driver.driverInfo;
    info.api_version = version_string(props.properties.apiVersion);
    info.vendor_id = props.properties.vendorID;
    info.device_id = props.properties.deviceID;
    return info;
}

}  // namespace

std::vector<DeviceInfo> GpuContext::list_devices() {
    VkInstance instance = create_instance(nullptr);
    std::vector<DeviceInfo> infos;
    auto devices = physical_devices(instance);
    for (size_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], int(i)));
    vkDestroyInstance(instance, nullptr);
    return infos;
}

void ValidationLog::add(const std::string& message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(message);
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

size_t ValidationLog::count() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

GpuContext::GpuContext(const std::string& selector, Validation validation) {
    if (validation == Validation::on || validation_requested()) {
        require_validation_layer();
        validation_log_ = std::make_shared<ValidationLog>();
    }
    instance_ = create_instance(validation_log_.get());
    if (validation_log_) {
        const VkDebugUtilsMessengerCreateInfoEXT info = messenger_info(validation_log_.get());
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw GpuError("the Vulkan validation layer offers no vkCreateDebugUtilsMessengerEXT");
        VK_CHECK(create(instance_, &info, nullptr, &messenger_));
    }

    auto devices = physical_devices(instance_);
    if (devices.empty()) throw GpuError("no Vulkan device found: install mesa-vulkan-drivers (scripts/install-deps)");
    std::vector<DeviceInfo> infos;
    for (size_t i = 0; i < devices.size(); ++i) infos.push_back(describe(devices[i], int(i)));

    int chosen = -1;
    if (selector.empty()) {
        for (const auto& d : infos)
            if (d.is_lavapipe()) { chosen = d.index; break; }
        if (chosen < 0) chosen = 0;
    } else if (std::all_of(selector.begin(), selector.end(), [](unsigned char c) { return std::isdigit(c); })) {
        int index = std::atoi(selector.c_str());
        if (index >= 0 && index < int(infos.size())) chosen = index;
    } else {
        for (const auto& d : infos)
            if (lower(d.name).find(lower(selector)) != std::string::npos) { chosen = d.index; break; }
    }
    if (chosen < 0) {
        std::string list;
        for (const auto& d : infos) list += fmt::format("\n    {}: {} ({})", d.index, d.name, d.driver_info);
        throw ConfigError({}, 0, fmt::format("no Vulkan device matches --device '{}'", selector),
                          "give an index or part of a name from `canopy devices`:" + list);
    }
    physical_ = devices[size_t(chosen)];
    info_ = infos[size_t(chosen)];

    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical_, &props);
    if (props.apiVersion < VK_API_VERSION_1_3)
        throw GpuError(fmt::format("device '{}' supports Vulkan {} but canopy needs 1.3", info_.name, info_.api_version));
    timestamp_period_ns_ = props.limits.timestampPeriod;
    vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);

    uint32_t family_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, nullptr);
    std::vector<VkQueueFamilyProperties> families(family_count);
    vkGetPhysicalDeviceQueueFamilyProperties(physical_, &family_count, families.data());
    bool found = false;
    for (uint32_t i = 0; i < family_count; ++i) {
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
            queue_family_ = i;
            timestamp_valid_bits_ = families[i].timestampValidBits;
            found = true;
            break;
        }
    }
    if (!found) throw GpuError(fmt::format("device '{}' has no graphics queue", info_.name));
    if (timestamp_valid_bits_ == 0)
        throw GpuError(fmt::format("device '{}' has no timestamp queries on its graphics queue; canopy times passes with them", info_.name));

    VkPhysicalDeviceVulkan13Features features13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features features12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    features13.pNext = &features12;
    VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    supported.pNext = &features13;
    vkGetPhysicalDeviceFeatures2(physical_, &supported);
    if (!features13.dynamicRendering || !features13.synchronization2)
        throw GpuError(fmt::format("device '{}' lacks dynamicRendering or synchronization2", info_.name));

    VkPhysicalDeviceVulkan13Features enable13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    enable13.dynamicRendering = VK_TRUE;
    enable13.synchronization2 = VK_TRUE;
    enable13.maintenance4 = features13.maintenance4;  // glslang's Vulkan 1.3 compute shaders use LocalSizeId
    // Draws whose count a compute pass wrote (the frame graph's indexed-indirect-count service).
    VkPhysicalDeviceVulkan12Features enable12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    enable12.drawIndirectCount = features12.drawIndirectCount;
    draw_indirect_count_ = features12.drawIndirectCount;
    enable13.pNext = &enable12;
    VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    enable.pNext = &enable13;
    enable.features.geometryShader = supported.features.geometryShader;
    enable.features.tessellationShader = supported.features.tessellationShader;
    enable.features.fillModeNonSolid = supported.features.fillModeNonSolid;
    // The triangles a frame submits and rasterises, counted in one untimed frame per case.
    enable.features.pipelineStatisticsQuery = supported.features.pipelineStatisticsQuery;
    pipeline_statistics_ = supported.features.pipelineStatisticsQuery;
    // Prefilter passes write any moment format through one unformatted image2D.
    enable.features.shaderStorageImageWriteWithoutFormat = supported.features.shaderStorageImageWriteWithoutFormat;
    storage_write_without_format_ = supported.features.shaderStorageImageWriteWithoutFormat;
    // Alpha-to-coverage stores 1 in the covered samples, so a resolved alpha is the covered share
    // of the pixel (the grass family's coverage) rather than alpha times it.
    enable.features.alphaToOne = supported.features.alphaToOne;
    enable.features.sampleRateShading = supported.features.sampleRateShading;
    sample_rate_shading_ = supported.features.sampleRateShading;
    // Anisotropic samplers (SamplerKind::anisotropic) where the device offers them, else trilinear.
    enable.features.samplerAnisotropy = supported.features.samplerAnisotropy;
    max_anisotropy_ = supported.features.samplerAnisotropy ? std::min(16.0f, props.limits.maxSamplerAnisotropy) : 1.0f;
    alpha_to_one_ = supported.features.alphaToOne;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queue_info{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queue_info.queueFamilyIndex = queue_family_;
    queue_info.queueCount = 1;
    queue_info.pQueuePriorities = &priority;
    VkDeviceCreateInfo device_info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    device_info.pNext = &enable;
    device_info.queueCreateInfoCount = 1;
    device_info.pQueueCreateInfos = &queue_info;
    VK_CHECK(vkCreateDevice(physical_, &device_info, nullptr, &device_));
    vkGetDeviceQueue(device_, queue_family_, 0, &queue_);

    VkCommandPoolCreateInfo pool_info{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pool_info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool_info.queueFamilyIndex = queue_family_;
    VK_CHECK(vkCreateCommandPool(device_, &pool_info, nullptr, &pool_));
    VkFenceCreateInfo fence_info{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VK_CHECK(vkCreateFence(device_, &fence_info, nullptr, &fence_));
}

GpuContext::~GpuContext() {
    if (device_) {
        vkDeviceWaitIdle(device_);
        vkDestroyFence(device_, fence_, nullptr);
        vkDestroyCommandPool(device_, pool_, nullptr);
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

uint32_t GpuContext::memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const {
    for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (memory_.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
    throw GpuError(fmt::format("device '{}' has no memory type with flags {:#x}", info_.name, wanted));
}

VkFormatFeatureFlags2 GpuContext::format_features(VkFormat format) const {
    VkFormatProperties3 props3{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
    VkFormatProperties2 props{VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2};
    props.pNext = &props3;
    vkGetPhysicalDeviceFormatProperties2(physical_, format, &props);
    return props3.optimalTilingFeatures;
}

VkCommandBuffer GpuContext::begin_commands() const {
    VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    alloc.commandPool = pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    VkCommandBuffer commands;
    VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &commands));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(commands, &begin));
    return commands;
}

void GpuContext::submit_and_wait(VkCommandBuffer commands) const {
    VK_CHECK(vkEndCommandBuffer(commands));
    VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
    VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, UINT64_MAX));
    VK_CHECK(vkResetFences(device_, 1, &fence_));
    vkFreeCommandBuffers(device_, pool_, 1, &commands);
}

const char* vk_result_name(VkResult result) {
    switch (result) {
        case VK_SUCCESS: return "VK_SUCCESS";
        case VK_NOT_READY: return "VK_NOT_READY";
        case VK_TIMEOUT: return "VK_TIMEOUT";
        case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
        case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
        case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
        case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
        case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
        case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
        case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
        case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
        case VK_ERROR_FORMAT_NOT_SUPPORTED: return "VK_ERROR_FORMAT_NOT_SUPPORTED";
        default: return "VkResult(other)";
    }
}

}  // namespace canopy
