// An image a compute pass writes and later passes sample or read back.
#pragma once

#include <vulkan/vulkan.h>

#include <glm/vec2.hpp>

#include "vk/resources.h"

namespace taa {

vk::Image storageImage(vk::Context& ctx, const char* name, glm::ivec2 size, VkFormat format);

}  // namespace taa
