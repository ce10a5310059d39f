#include "vk/check.h"

namespace taa::vk {

const char* resultName(VkResult result) {
  switch (result) {
#define TAA_CASE(x) \
  case x:           \
    return #x;
    TAA_CASE(VK_SUCCESS)
    TAA_CASE(VK_NOT_READY)
    TAA_CASE(VK_TIMEOUT)
    TAA_CASE(VK_INCOMPLETE)
    TAA_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    TAA_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    TAA_CASE(VK_ERROR_INITIALIZATION_FAILED)
    TAA_CASE(VK_ERROR_DEVICE_LOST)
    TAA_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    TAA_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    TAA_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    TAA_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    TAA_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    TAA_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    TAA_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    TAA_CASE(VK_ERROR_FRAGMENTED_POOL)
    TAA_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    TAA_CASE(VK_ERROR_UNKNOWN)
#undef TAA_CASE
    default:
      return "VK_ERROR_(unnamed)";
  }
}

void throwVkError(VkResult result, const char* call, const char* file, int line) {
  throw VulkanError(result, std::string(file) + ":" + std::to_string(line) + ": " + call + " failed with " +
                                resultName(result));
}

}  // namespace taa::vk
