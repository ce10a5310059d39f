// The one error check of the Vulkan layer: a failing call becomes an exception that
// carries the call's text, file and line. Never compiled out.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "api/device_error.h"

namespace taa::vk {

class VulkanError : public DeviceError {
 public:
  VulkanError(VkResult result, const std::string& what) : DeviceError(what), result_(result) {}
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

// The environment cannot run the renderer (no device, missing shaders, missing
// feature). The CLI maps it to exit code 3; the message says what to install.
using EnvironmentError = ::taa::EnvironmentError;

const char* resultName(VkResult result);

[[noreturn]] void throwVkError(VkResult result, const char* call, const char* file, int line);

}  // namespace taa::vk

#define VK_CHECK(call)                                                             \
  do {                                                                             \
    const VkResult taa_vk_result_ = (call);                                        \
    if (taa_vk_result_ != VK_SUCCESS)                                              \
      ::taa::vk::throwVkError(taa_vk_result_, #call, __FILE__, __LINE__);          \
  } while (0)
