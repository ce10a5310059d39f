// Headless Vulkan 1.3 context: instance, one device (lavapipe unless asked
// otherwise), one queue, one command pool. No surface, no swapchain.
#pragma once

#include <vulkan/vulkan.h>

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace taa::vk {

class PipelineCache;

struct ContextOptions {
  // Case-insensitive substring of the device name; empty: $TAA_DEVICE, else lavapipe.
  std::string device;
  bool validate = false;  // Khronos validation layer; messages are counted and printed
  // Mesa's shader cache folder (see shaderCacheDir() in vk/shader_cache.h); empty disables it.
  std::filesystem::path shaderCacheDir;
  // Devices of this process that render at the same time; with more than one, each lavapipe
  // device gets its share of the cores as rasteriser threads (Context's constructor).
  int devicesAtOnce = 1;
};

// Identity of the driver a frame came from; goldens record it.
struct DeviceInfo {
  std::string name;        // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driverName;  // e.g. "llvmpipe"
  std::string driverInfo;  // e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  uint32_t apiVersion = 0;
  uint32_t driverVersion = 0;
  uint32_t vendorId = 0;
  uint32_t deviceId = 0;
  bool isCpu = false;
  float timestampPeriodNs = 1.0f;
  uint32_t maxPushDescriptors = 0;  // the adaptive tracer pushes a texture array
};

class Context {
 public:
  explicit Context(const ContextOptions& options);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkDevice device() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  const DeviceInfo& info() const { return info_; }

  uint32_t memoryType(uint32_t typeBits, VkMemoryPropertyFlags wanted) const;

  VkCommandBuffer beginCommands();
  // Submits, waits for completion and frees the command buffer.
  void submitAndWait(VkCommandBuffer cmd);

  void pushDescriptorSet(VkCommandBuffer cmd, VkPipelineBindPoint bindPoint, VkPipelineLayout layout,
                         uint32_t set, uint32_t count, const VkWriteDescriptorSet* writes) const;

  // Validation messages of severity warning or error seen so far.
  int validationMessages() const { return validationMessages_.load(); }

  // Every pipeline made on this device, by what shapes it (vk/pipeline_cache.h).
  PipelineCache& pipelines() { return *pipelines_; }

 private:
  // Each returns false where it would throw, unless `mustSucceed` (the last try).
  bool createInstance(bool validate, bool mustSucceed);
  bool pickDevice(const std::string& wanted, bool mustSucceed);
  void destroyInstance();
  void createDevice();

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
  PFN_vkCmdPushDescriptorSetKHR pushDescriptorSet_ = nullptr;
  DeviceInfo info_;
  std::atomic<int> validationMessages_{0};
  std::unique_ptr<PipelineCache> pipelines_;
};

}  // namespace taa::vk
