#include "vk/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

#include "core/cpu_cores.h"
#include "vk/check.h"
#include "vk/driver_manifests.h"
#include "vk/pipeline_cache.h"

namespace taa::vk {

namespace {

const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";
const char* kNoDeviceFix =
    "install a Vulkan driver: on Debian, apt-get install mesa-vulkan-drivers libvulkan1 (lavapipe)";

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* user) {
  if (severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) {
    ++*static_cast<std::atomic<int>*>(user);
    std::cerr << "validation: " << data->pMessage << "\n";
  }
  return VK_FALSE;
}

bool hasLayer(const char* name) {
  uint32_t count = 0;
  vkEnumerateInstanceLayerProperties(&count, nullptr);
  std::vector<VkLayerProperties> layers(count);
  vkEnumerateInstanceLayerProperties(&count, layers.data());
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

// lavapipe rasterises a device's draws on LP_NUM_THREADS threads, one per core by default.
// Devices rendering at once (run -j N) would each start one per core; on cores they already
// keep busy, the hand-offs between those threads cost CPU and add nothing (the main job on
// 2 cores: 13% more CPU with them). So each device gets its share of the cores, and with a
// share of one core it rasterises on its own thread (0). Frames do not depend on the thread
// count (tests: AdaptiveDeterminism, ParallelRun). A user's own LP_NUM_THREADS stands.
void shareCoresAmong(int devices) {
  static const bool userSet = std::getenv("LP_NUM_THREADS") != nullptr;
  if (userSet) return;
  if (devices <= 1) {
    unsetenv("LP_NUM_THREADS");
    return;
  }
  const size_t share = availableCores() / size_t(devices);
  setenv("LP_NUM_THREADS", std::to_string(share >= 2 ? share : 0).c_str(), 1);
}

}  // namespace

Context::Context(const ContextOptions& options) {
  shareCoresAmong(options.devicesAtOnce);
  // Mesa reads these when the driver loads; set them before the instance exists.
  if (options.shaderCacheDir.empty()) {
    setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  } else {
    setenv("MESA_SHADER_CACHE_DIR", options.shaderCacheDir.c_str(), 1);
    unsetenv("MESA_SHADER_CACHE_DISABLE");
  }
  std::string wanted = options.device;
  if (wanted.empty())
    if (const char* env = std::getenv("TAA_DEVICE")) wanted = env;
  // lavapipe wanted: its driver alone is loaded (vk/driver_manifests.h). A manifest that names
  // lavapipe but gives no device (a broken or other-architecture install) falls back to every
  // driver the loader finds, so the choice never loses a device the user has.
  const std::string onlyLavapipe = wanted.empty() ? lavapipeOnlyDriverFiles(std::getenv) : "";
  if (!onlyLavapipe.empty()) {
    setenv("VK_DRIVER_FILES", onlyLavapipe.c_str(), 1);
    const bool found = createInstance(options.validate, false) && pickDevice(wanted, false);
    unsetenv("VK_DRIVER_FILES");
    if (!found) destroyInstance();
  }
  if (!instance_) {
    createInstance(options.validate, true);
    pickDevice(wanted, true);
  }
  createDevice();
  pipelines_ = std::make_unique<PipelineCache>();
}

Context::~Context() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    pipelines_.reset();  // its pipelines belong to the device
    vkDestroyFence(device_, fence_, nullptr);
    vkDestroyCommandPool(device_, pool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  destroyInstance();
}

void Context::destroyInstance() {
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
  messenger_ = VK_NULL_HANDLE;
  instance_ = VK_NULL_HANDLE;
  physical_ = VK_NULL_HANDLE;
}

bool Context::createInstance(bool validate, bool mustSucceed) {
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "taa-harness";
  app.apiVersion = VK_API_VERSION_1_3;

  std::vector<const char*> layers, extensions;
  if (validate) {
    if (!hasLayer(kValidationLayer))
      throw EnvironmentError(
          "--validate needs the Khronos validation layer: apt-get install vulkan-validationlayers");
    layers.push_back(kValidationLayer);
    extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  }
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  info.enabledLayerCount = uint32_t(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = uint32_t(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  const VkResult r = vkCreateInstance(&info, nullptr, &instance_);
  const bool noDriver = r == VK_ERROR_INCOMPATIBLE_DRIVER || r == VK_ERROR_INITIALIZATION_FAILED;
  if (noDriver && !mustSucceed) {
    instance_ = VK_NULL_HANDLE;
    return false;
  }
  if (noDriver)
    throw EnvironmentError(std::string("no Vulkan 1.3 driver found (") + resultName(r) + "); " + kNoDeviceFix);
  VK_CHECK(r);

  if (validate) {
    VkDebugUtilsMessengerCreateInfoEXT m{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    m.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    m.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                    VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    m.pfnUserCallback = onValidationMessage;
    m.pUserData = &validationMessages_;
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
    VK_CHECK(create(instance_, &m, nullptr, &messenger_));
  }
  return true;
}

bool Context::pickDevice(const std::string& wanted, bool mustSucceed) {
  uint32_t count = 0;
  const VkResult listed = vkEnumeratePhysicalDevices(instance_, &count, nullptr);
  if (listed != VK_SUCCESS && !mustSucceed) return false;
  VK_CHECK(listed);
  std::vector<VkPhysicalDevice> devices(count);
  VK_CHECK(vkEnumeratePhysicalDevices(instance_, &count, devices.data()));
  if (devices.empty() && !mustSucceed) return false;
  if (devices.empty()) throw EnvironmentError(std::string("no Vulkan device found; ") + kNoDeviceFix);

  std::string names;
  for (auto d : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(d, &p);
    names += std::string(names.empty() ? "" : ", ") + p.deviceName;
    const bool isCpu = p.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    const bool match = wanted.empty() ? isCpu : lower(p.deviceName).find(lower(wanted)) != std::string::npos;
    if (match && VK_API_VERSION_MINOR(p.apiVersion) >= 3 && !physical_) physical_ = d;
  }
  if (!physical_ && !mustSucceed) return false;
  if (!physical_) {
    if (wanted.empty())
      throw EnvironmentError("no lavapipe (llvmpipe) Vulkan 1.3 device among: " + names +
                             "; apt-get install mesa-vulkan-drivers, or pick one with --device NAME");
    throw EnvironmentError("no Vulkan 1.3 device matches '" + wanted + "' among: " + names +
                           "; pass part of one of these names to --device (or $TAA_DEVICE)");
  }

  VkPhysicalDeviceDriverProperties driver{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver};
  vkGetPhysicalDeviceProperties2(physical_, &props);
  info_.name = props.properties.deviceName;
  info_.driverName = driver.driverName;
  info_.driverInfo = driver.driverInfo;
  info_.apiVersion = props.properties.apiVersion;
  info_.driverVersion = props.properties.driverVersion;
  info_.vendorId = props.properties.vendorID;
  info_.deviceId = props.properties.deviceID;
  info_.isCpu = props.properties.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  info_.timestampPeriodNs = props.properties.limits.timestampPeriod;
  return true;
}

void Context::createDevice() {
  uint32_t familyCount = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, nullptr);
  std::vector<VkQueueFamilyProperties> families(familyCount);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &familyCount, families.data());
  bool found = false;
  for (uint32_t i = 0; i < familyCount && !found; ++i) {
    const auto f = families[i];
    if ((f.queueFlags & VK_QUEUE_GRAPHICS_BIT) && (f.queueFlags & VK_QUEUE_COMPUTE_BIT) && f.timestampValidBits > 0) {
      queueFamily_ = i;
      found = true;
    }
  }
  if (!found) throw EnvironmentError(info_.name + " has no graphics+compute queue with timestamps");

  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features f12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &f13};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f12};
  vkGetPhysicalDeviceFeatures2(physical_, &supported);
  if (!f13.dynamicRendering || !f13.synchronization2 || !f12.hostQueryReset)
    throw EnvironmentError(info_.name + " lacks dynamicRendering, synchronization2 or hostQueryReset");

  VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  e13.dynamicRendering = VK_TRUE;
  e13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceVulkan12Features e12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &e13};
  e12.hostQueryReset = VK_TRUE;
  VkPhysicalDevicePushDescriptorPropertiesKHR push{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PUSH_DESCRIPTOR_PROPERTIES_KHR};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &push};
  vkGetPhysicalDeviceProperties2(physical_, &props);
  info_.maxPushDescriptors = push.maxPushDescriptors;
  VkPhysicalDeviceFeatures2 enabled{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &e12};
  enabled.features.shaderStorageImageWriteWithoutFormat = supported.features.shaderStorageImageWriteWithoutFormat;
  if (!supported.features.independentBlend)
    throw EnvironmentError(info_.name + " lacks independentBlend (blended surfaces must leave the other targets alone)");
  enabled.features.independentBlend = VK_TRUE;

  const float priority = 1.0f;
  VkDeviceQueueCreateInfo q{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  q.queueFamilyIndex = queueFamily_;
  q.queueCount = 1;
  q.pQueuePriorities = &priority;
  const char* extensions[] = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enabled};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &q;
  info.enabledExtensionCount = 1;
  info.ppEnabledExtensionNames = extensions;
  const VkResult r = vkCreateDevice(physical_, &info, nullptr, &device_);
  if (r == VK_ERROR_EXTENSION_NOT_PRESENT)
    throw EnvironmentError(info_.name + " lacks VK_KHR_push_descriptor, which the renderer needs");
  VK_CHECK(r);
  vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
  pushDescriptorSet_ = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = queueFamily_;
  VK_CHECK(vkCreateCommandPool(device_, &pool, nullptr, &pool_));
  VkFenceCreateInfo fence{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vkCreateFence(device_, &fence, nullptr, &fence_));
}

uint32_t Context::memoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const {
  VkPhysicalDeviceMemoryProperties mem;
  vkGetPhysicalDeviceMemoryProperties(physical_, &mem);
  for (uint32_t i = 0; i < mem.memoryTypeCount; ++i)
    if ((typeBits & (1u << i)) && (mem.memoryTypes[i].propertyFlags & wanted) == wanted) return i;
  throw EnvironmentError(info_.name + " has no memory type with the required properties");
}

VkCommandBuffer Context::beginCommands() {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = pool_;
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd;
  VK_CHECK(vkAllocateCommandBuffers(device_, &alloc, &cmd));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vkBeginCommandBuffer(cmd, &begin));
  return cmd;
}

void Context::submitAndWait(VkCommandBuffer cmd) {
  VK_CHECK(vkEndCommandBuffer(cmd));
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &cmd;
  VK_CHECK(vkQueueSubmit(queue_, 1, &submit, fence_));
  // A bounded wait: a wedged driver becomes an error (VK_TIMEOUT), never a hang.
  constexpr uint64_t kTimeoutNs = 300ull * 1000 * 1000 * 1000;
  VK_CHECK(vkWaitForFences(device_, 1, &fence_, VK_TRUE, kTimeoutNs));
  VK_CHECK(vkResetFences(device_, 1, &fence_));
  vkFreeCommandBuffers(device_, pool_, 1, &cmd);
}

void Context::pushDescriptorSet(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, VkPipelineLayout layout,
                                uint32_t set, uint32_t count, const VkWriteDescriptorSet* writes) const {
  pushDescriptorSet_(cmd, bindPoint, layout, set, count, writes);
}

}  // namespace taa::vk
