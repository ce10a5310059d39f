// Turns the bytes of a read-back target into a float Image (top-left crop of the
// frame's render size; dynamic resolution renders into part of the target).
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "core/image.h"

namespace taa {

// RGBA16F -> 4 channels, RG16F -> 2, R32_SFLOAT/D32 -> 1, R32_UINT ids -> 3
// (object id, material id, mover flag; sky is -1, -1, 0).
Image decodeTarget(const uint8_t* bytes, VkFormat format, int targetWidth, int width, int height);
inline Image decodeTarget(const std::vector<uint8_t>& bytes, VkFormat format, int targetWidth,
                          int width, int height) {
  return decodeTarget(bytes.data(), format, targetWidth, width, height);
}

}  // namespace taa
