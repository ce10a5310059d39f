// Global memory barriers, for what Image::use() does not cover: buffers written by one
// pass and read by the next (storage, indirect arguments, transfers, the host).
#pragma once

#include <vulkan/vulkan.h>

namespace taa::vk {

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

}  // namespace taa::vk
