// Images compute passes write, sample or bind without reading.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>

#include "vk/resources.h"

namespace taa {

// An image a compute pass writes and later passes sample or read back.
vk::ImageDesc storageImageDesc(const char* name, glm::ivec2 size, VkFormat format);
vk::Image storageImage(vk::Context& ctx, const char* name, glm::ivec2 size, VkFormat format);

// `desc` (transfer-destination use added) cleared to zero and left in `use`: a target read
// before anything writes it (a reset frame's history) or a binding a variant never reads
// holds zeros, never undefined memory.
vk::Image zeroedImage(vk::Context& ctx, vk::ImageDesc desc, vk::Use use);

}  // namespace taa
