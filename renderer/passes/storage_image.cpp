#include "passes/storage_image.h"

namespace taa {

vk::Image storageImage(vk::Context& ctx, const char* name, glm::ivec2 size, VkFormat format) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(size.x);
  d.height = uint32_t(size.y);
  d.format = format;
  d.usage = VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return vk::Image(ctx, d);
}

}  // namespace taa
