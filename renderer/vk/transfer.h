// Moving bytes between the host and device-local resources through staging buffers.
#pragma once

#include <cstdint>
#include <vector>

#include "vk/resources.h"

namespace taa::vk {

class Context;

Buffer uploadBuffer(Context& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage);

// Uploads each mip level (tightly packed texels of the image's format) and leaves
// the image ready for sampling in fragment shaders.
void uploadImage(Context& ctx, Image& image, const std::vector<const void*>& levels);

// Copies one array layer of mip 0 to the host, tightly packed.
std::vector<uint8_t> readImage(Context& ctx, Image& image, uint32_t layer = 0);

}  // namespace taa::vk
