#include "tessera/gpu/Instance.h"

#include "tessera/core/Log.h"
#include "tessera/gpu/VulkanCheck.h"

#include <GLFW/glfw3.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <charconv>
#include <cstring>

namespace tessera::gpu {
namespace {

std::atomic<uint64_t> sValidationMessages{0};
constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onDebugMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                              VkDebugUtilsMessageTypeFlagsEXT, const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void*) {
    // Warnings and errors are what "any validation message fails" means;
    // info and verbose are the loader's chatter.
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    ++sValidationMessages;
    std::string text = "validation: ";
    text += data->pMessage ? data->pMessage : "(no message)";
    log::error(text);
    return VK_FALSE;
}

bool hasLayer(const char* name) {
    uint32_t count = 0;
    vkEnumerateInstanceLayerProperties(&count, nullptr);
    std::vector<VkLayerProperties> layers(count);
    vkEnumerateInstanceLayerProperties(&count, layers.data());
    return std::any_of(layers.begin(), layers.end(), [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasDeviceExtension(VkPhysicalDevice device, const char* name) {
    uint32_t count = 0;
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr);
    std::vector<VkExtensionProperties> exts(count);
    vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data());
    return std::any_of(exts.begin(), exts.end(), [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

/// The mesh-shader limits of a device that has both stages. Its queries
/// count only where pipeline statistics exist (they extend those).
void readMeshShader(VkPhysicalDevice device, bool queries, device::DeviceFeatures& f) {
    VkPhysicalDeviceMeshShaderPropertiesEXT mesh{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_PROPERTIES_EXT};
    VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &mesh};
    vkGetPhysicalDeviceProperties2(device, &props);
    f.meshShader = true;
    f.meshShaderQueries = queries && f.pipelineStatistics;
    f.maxMeshOutputVertices = mesh.maxMeshOutputVertices;
    f.maxMeshOutputPrimitives = mesh.maxMeshOutputPrimitives;
    f.maxMeshWorkGroupInvocations = mesh.maxMeshWorkGroupInvocations;
    f.maxTaskPayloadSize = mesh.maxTaskPayloadSize;
}

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
    }
}

} // namespace

const char* deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
    default: return "other";
    }
}

uint64_t Instance::validationMessageCount() { return sValidationMessages.load(); }

Result<std::unique_ptr<Instance>> Instance::create(const InstanceOptions& options) {
    uint32_t loaderVersion = 0;
    if (vkEnumerateInstanceVersion(&loaderVersion) != VK_SUCCESS || loaderVersion < VK_API_VERSION_1_3)
        return fail("Vulkan 1.3 is required but the loader reports ", std::to_string(VK_API_VERSION_MAJOR(loaderVersion)),
                    ".", std::to_string(VK_API_VERSION_MINOR(loaderVersion)),
                    "; install libvulkan1 and mesa-vulkan-drivers (see README)");

    std::vector<const char*> extensions = {VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    if (options.windowing) {
        uint32_t count = 0;
        const char** glfwExts = glfwGetRequiredInstanceExtensions(&count);
        if (!glfwExts) return failSetting("window", ": GLFW found no Vulkan surface support on this display");
        extensions.insert(extensions.end(), glfwExts, glfwExts + count);
    }
    std::vector<const char*> layers;
    if (options.validation) {
        if (!hasLayer(kValidationLayer))
            return failSetting("validation", ": the Khronos validation layer (", kValidationLayer,
                               ") is not installed; install the Debian package vulkan-validationlayers");
        layers.push_back(kValidationLayer);
    }

    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "Tessera";
    app.pEngineName = "Tessera";
    app.apiVersion = VK_API_VERSION_1_3;

    VkDebugUtilsMessengerCreateInfoEXT messenger{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    messenger.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    messenger.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                            VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    messenger.pfnUserCallback = onDebugMessage;

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    info.enabledExtensionCount = static_cast<uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    info.enabledLayerCount = static_cast<uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    // Chained so that messages from instance creation itself are counted too.
    if (options.validation) info.pNext = &messenger;

    std::unique_ptr<Instance> instance(new Instance());
    VkResult result = vkCreateInstance(&info, nullptr, &instance->mInstance);
    if (result != VK_SUCCESS)
        return fail("could not create a Vulkan instance (", resultName(result), "); is a Vulkan driver installed?");

    if (options.validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance->mInstance, "vkCreateDebugUtilsMessengerEXT"));
        if (!create || create(instance->mInstance, &messenger, nullptr, &instance->mMessenger) != VK_SUCCESS)
            return failSetting("validation", ": could not install the debug messenger");
    }
    instance->mWindowing = options.windowing;
    instance->enumerate();
    if (instance->mDevices.empty())
        return fail("no Vulkan 1.3 device with dynamic rendering, synchronization2 and push descriptors was found; "
                    "install mesa-vulkan-drivers for lavapipe");
    return instance;
}

Instance::~Instance() {
    if (mMessenger) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(mInstance, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(mInstance, mMessenger, nullptr);
    }
    if (mInstance) vkDestroyInstance(mInstance, nullptr);
}

void Instance::enumerate() {
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(mInstance, &count, nullptr);
    std::vector<VkPhysicalDevice> handles(count);
    vkEnumeratePhysicalDevices(mInstance, &count, handles.data());

    for (uint32_t i = 0; i < count; ++i) {
        VkPhysicalDevice pd = handles[i];
        VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
        vkGetPhysicalDeviceProperties2(pd, &props);
        if (props.properties.apiVersion < VK_API_VERSION_1_3) continue;

        VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT};
        VkPhysicalDeviceMeshShaderFeaturesEXT mesh{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MESH_SHADER_FEATURES_EXT};
        VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
        VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v13};
        const bool hasXfb = hasDeviceExtension(pd, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME);
        const bool hasMesh = hasDeviceExtension(pd, VK_EXT_MESH_SHADER_EXTENSION_NAME);
        if (hasXfb) {
            xfb.pNext = v13.pNext;
            v13.pNext = &xfb;
        }
        if (hasMesh) {
            mesh.pNext = v13.pNext;
            v13.pNext = &mesh;
        }
        vkGetPhysicalDeviceFeatures2(pd, &features);
        if (!v13.dynamicRendering || !v13.synchronization2 || !hasDeviceExtension(pd, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
            continue;

        PhysicalDeviceInfo info;
        info.handle = pd;
        info.index = static_cast<uint32_t>(mDevices.size());
        info.type = props.properties.deviceType;
        info.apiVersion = props.properties.apiVersion;
        auto& f = info.features;
        f.deviceName = props.properties.deviceName;
        f.driverName = driver.driverName;
        f.driverInfo = driver.driverInfo;
        f.isCpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
        f.tessellationShader = features.features.tessellationShader;
        f.geometryShader = features.features.geometryShader;
        f.transformFeedback = hasXfb && xfb.transformFeedback;
        f.pipelineStatistics = features.features.pipelineStatisticsQuery;
        f.timestamps = props.properties.limits.timestampComputeAndGraphics;
        f.fillModeNonSolid = features.features.fillModeNonSolid;
        f.vertexStores = features.features.vertexPipelineStoresAndAtomics;
        f.multiDrawIndirect = features.features.multiDrawIndirect && features.features.drawIndirectFirstInstance;
        f.maxTessellationLevel = f.tessellationShader ? props.properties.limits.maxTessellationGenerationLevel : 0;
        // Both stages or neither: the backend that uses them amplifies in
        // the task stage.
        if (hasMesh && mesh.taskShader && mesh.meshShader) readMeshShader(pd, mesh.meshShaderQueries, f);
        mDevices.push_back(std::move(info));
    }
}

Result<PhysicalDeviceInfo> Instance::selectDevice(const std::string& selector) const {
    auto listing = [&] {
        std::string out;
        for (const auto& d : mDevices) out += "\n  " + std::to_string(d.index) + ": " + d.features.deviceName;
        return out;
    };
    if (selector.empty()) {
        auto best = std::min_element(mDevices.begin(), mDevices.end(),
                                     [](const auto& a, const auto& b) { return typeRank(a.type) < typeRank(b.type); });
        return *best;
    }
    unsigned index = 0;
    auto [end, ec] = std::from_chars(selector.data(), selector.data() + selector.size(), index);
    if (ec == std::errc() && end == selector.data() + selector.size()) {
        if (index < mDevices.size()) return mDevices[index];
        return failSetting("device", " ", selector, ": there is no device with that index; devices:", listing());
    }
    for (const auto& d : mDevices)
        if (lower(d.features.deviceName).find(lower(selector)) != std::string::npos) return d;
    return failSetting("device", " ", selector, ": no device name contains that text; devices:", listing());
}

} // namespace tessera::gpu
