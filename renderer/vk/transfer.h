// Moving bytes between the host and device-local resources through staging buffers.
#pragma once

#include <cstdint>
#include <vector>

#include "vk/resources.h"
#include "vk/staging_ring.h"  // readImage, the host-bound direction

namespace taa::vk {

class Context;

Buffer uploadBuffer(Context& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage);

// Uploads each mip level (tightly packed texels of the image's format) and leaves
// the image ready for sampling in fragment shaders.
void uploadImage(Context& ctx, Image& image, const std::vector<const void*>& levels);

}  // namespace taa::vk
