#include "vulkan_context.h"

#include "device_choice.h"
#include "vulkan_error.h"
#include "vulkan_library.h"

#include <cstdlib>
#include <cstring>
#include <iostream>
#include <vector>

namespace roomsense::compute {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool has_layer(const GlobalFunctions& g, const char* name) {
  std::uint32_t count = 0;
  if (g.vkEnumerateInstanceLayerProperties(&count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkLayerProperties> layers(count);
  if (g.vkEnumerateInstanceLayerProperties(&count, layers.data()) != VK_SUCCESS) return false;
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

bool has_instance_extension(const GlobalFunctions& g, const char* layer, const char* name) {
  std::uint32_t count = 0;
  if (g.vkEnumerateInstanceExtensionProperties(layer, &count, nullptr) != VK_SUCCESS) return false;
  std::vector<VkExtensionProperties> exts(count);
  if (g.vkEnumerateInstanceExtensionProperties(layer, &count, exts.data()) != VK_SUCCESS) return false;
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

bool env_flag(const char* name) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' && std::strcmp(v, "0") != 0;
}

}  // namespace

GpuKind gpu_kind(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return GpuKind::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return GpuKind::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return GpuKind::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return GpuKind::Cpu;
    default: return GpuKind::Other;
  }
}

std::unique_ptr<VulkanContext> VulkanContext::create(const ContextOptions& options, std::string* why_not) {
  std::unique_ptr<VulkanContext> ctx(new VulkanContext());
  try {
    ctx->init(options);
    return ctx;
  } catch (const std::exception& e) {
    if (why_not != nullptr) *why_not = e.what();
    return nullptr;
  }
}

VulkanContext::~VulkanContext() {
  // Order: wait, device, messenger, then the instance (a member).
  if (device_ && device_fns_.vkDeviceWaitIdle != nullptr) device_fns_.vkDeviceWaitIdle(device_->get());
  device_.reset();
  if (messenger_ != VK_NULL_HANDLE && instance_) instance_fns_.vkDestroyDebugUtilsMessengerEXT(instance_->get(), messenger_, nullptr);
}

void VulkanContext::log(std::string_view line) const {
  if (log_) {
    log_(line);
  } else {
    std::cerr << "roomsense: vulkan: " << line << '\n';
  }
}

VkDebugUtilsMessengerCreateInfoEXT VulkanContext::messenger_info() {
  VkDebugUtilsMessengerCreateInfoEXT info{};
  info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = &VulkanContext::on_debug_message;
  info.pUserData = this;
  return info;
}

VKAPI_ATTR VkBool32 VKAPI_CALL VulkanContext::on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                                VkDebugUtilsMessageTypeFlagsEXT,
                                                                const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                                void* user) {
  auto* self = static_cast<VulkanContext*>(user);
  self->validation_messages_.fetch_add(1);
  std::string line = severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT ? "validation error: " : "validation warning: ";
  line += data != nullptr && data->pMessage != nullptr ? data->pMessage : "(no message)";
  self->log(line);
  return VK_FALSE;  // never abort the call
}

void VulkanContext::init(const ContextOptions& options) {
  log_ = options.log;
  std::string why;
  const VulkanLibrary* library = VulkanLibrary::get(&why);
  if (library == nullptr) throw std::runtime_error(why);
  const GlobalFunctions& g = library->functions();

  std::uint32_t loader_version = 0;
  check(g.vkEnumerateInstanceVersion(&loader_version), "vkEnumerateInstanceVersion");
  if (loader_version < VK_API_VERSION_1_1) throw std::runtime_error("the Vulkan loader is older than Vulkan 1.1");

  // Validation: the layer, and debug utils for the messenger that counts its messages.
  std::vector<const char*> layers, extensions;
  const bool want_validation = options.validation || env_flag("ROOMSENSE_VULKAN_VALIDATION");
  if (want_validation) {
    if (!has_layer(g, kValidationLayer)) {
      if (options.require_validation)
        throw std::runtime_error("validation was required but VK_LAYER_KHRONOS_validation is not installed "
                                 "(Debian: apt-get install vulkan-validationlayers)");
      log("validation requested but VK_LAYER_KHRONOS_validation is not installed; going on without it");
    } else if (!has_instance_extension(g, nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) &&
               !has_instance_extension(g, kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
      if (options.require_validation) throw std::runtime_error("validation was required but VK_EXT_debug_utils is missing");
      log("VK_EXT_debug_utils is missing; going on without validation");
    } else {
      layers.push_back(kValidationLayer);
      extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
      validation_enabled_ = true;
    }
  }

  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "roomsense";
  app.pEngineName = "roomsense";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ici{};
  ici.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = std::uint32_t(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = std::uint32_t(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  // Chained so that instance creation and destruction are validated too.
  VkDebugUtilsMessengerCreateInfoEXT creation_messenger = messenger_info();
  if (validation_enabled_) ici.pNext = &creation_messenger;
  VkInstance instance = VK_NULL_HANDLE;
  check(g.vkCreateInstance(&ici, nullptr, &instance), "vkCreateInstance");
  const auto destroy_instance =
      reinterpret_cast<PFN_vkDestroyInstance>(g.vkGetInstanceProcAddr(instance, "vkDestroyInstance"));
  instance_.emplace(instance, destroy_instance);

#define ROOMSENSE_VK_LOAD(name)                                                                  \
  instance_fns_.name = reinterpret_cast<PFN_##name>(g.vkGetInstanceProcAddr(instance, #name)); \
  if (instance_fns_.name == nullptr) throw std::runtime_error("the Vulkan loader lacks " #name);
  ROOMSENSE_VK_INSTANCE_FUNCTIONS(ROOMSENSE_VK_LOAD)
  if (validation_enabled_) {
    ROOMSENSE_VK_DEBUG_FUNCTIONS(ROOMSENSE_VK_LOAD)
  }
#undef ROOMSENSE_VK_LOAD
  if (validation_enabled_) {
    const VkDebugUtilsMessengerCreateInfoEXT mi = messenger_info();
    check(instance_fns_.vkCreateDebugUtilsMessengerEXT(instance, &mi, nullptr, &messenger_), "vkCreateDebugUtilsMessengerEXT");
  }

  // The physical device (device_choice.h).
  std::uint32_t count = 0;
  check(instance_fns_.vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
  if (count == 0) throw std::runtime_error("no Vulkan device (no GPU driver and no lavapipe: apt-get install mesa-vulkan-drivers)");
  std::vector<VkPhysicalDevice> devices(count);
  const VkResult enumerated = instance_fns_.vkEnumeratePhysicalDevices(instance, &count, devices.data());
  if (enumerated != VK_SUCCESS && enumerated != VK_INCOMPLETE) check(enumerated, "vkEnumeratePhysicalDevices");
  devices.resize(count);
  std::vector<DeviceCandidate> candidates;
  std::vector<std::uint32_t> compute_family(count, 0);
  for (std::uint32_t i = 0; i < count; ++i) {
    VkPhysicalDeviceProperties p{};
    instance_fns_.vkGetPhysicalDeviceProperties(devices[i], &p);
    std::uint32_t families = 0;
    instance_fns_.vkGetPhysicalDeviceQueueFamilyProperties(devices[i], &families, nullptr);
    std::vector<VkQueueFamilyProperties> fp(families);
    instance_fns_.vkGetPhysicalDeviceQueueFamilyProperties(devices[i], &families, fp.data());
    DeviceCandidate c;
    c.type = p.deviceType;
    c.api_version = p.apiVersion;
    c.max_storage_buffers_per_stage = p.limits.maxPerStageDescriptorStorageBuffers;
    for (std::uint32_t f = 0; f < families; ++f)
      if ((fp[f].queueFlags & VK_QUEUE_COMPUTE_BIT) != 0 && fp[f].queueCount > 0) {
        c.has_compute_queue = true;
        compute_family[i] = f;
        break;
      }
    candidates.push_back(c);
  }
  const int chosen = choose_device(candidates);
  if (chosen < 0) throw std::runtime_error("no Vulkan 1.1 device with a compute queue");
  physical_ = devices[std::size_t(chosen)];
  queue_family_ = compute_family[std::size_t(chosen)];
  instance_fns_.vkGetPhysicalDeviceProperties(physical_, &properties_);
  instance_fns_.vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  {
    std::uint32_t families = 0;
    instance_fns_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, nullptr);
    std::vector<VkQueueFamilyProperties> fp(families);
    instance_fns_.vkGetPhysicalDeviceQueueFamilyProperties(physical_, &families, fp.data());
    timestamp_valid_bits_ = fp[queue_family_].timestampValidBits;
  }
  info_.name = properties_.deviceName;
  info_.kind = gpu_kind(properties_.deviceType);
  if (!options.create_device) return;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qi{};
  qi.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qi.queueFamilyIndex = queue_family_;
  qi.queueCount = 1;
  qi.pQueuePriorities = &priority;
  VkDeviceCreateInfo di{};
  di.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  di.queueCreateInfoCount = 1;
  di.pQueueCreateInfos = &qi;
  VkDevice device = VK_NULL_HANDLE;
  check(instance_fns_.vkCreateDevice(physical_, &di, nullptr, &device), "vkCreateDevice");
  const auto destroy_device = reinterpret_cast<PFN_vkDestroyDevice>(instance_fns_.vkGetDeviceProcAddr(device, "vkDestroyDevice"));
  device_.emplace(device, destroy_device);
#define ROOMSENSE_VK_LOAD(name)                                                                          \
  device_fns_.name = reinterpret_cast<PFN_##name>(instance_fns_.vkGetDeviceProcAddr(device, #name)); \
  if (device_fns_.name == nullptr) throw std::runtime_error("the Vulkan driver lacks " #name);
  ROOMSENSE_VK_DEVICE_FUNCTIONS(ROOMSENSE_VK_LOAD)
#undef ROOMSENSE_VK_LOAD
  device_fns_.vkGetDeviceQueue(device, queue_family_, 0, &queue_);
}

}  // namespace roomsense::compute
