#include "passes/storage_image.h"

#include "vk/context.h"

namespace taa {

vk::ImageDesc storageImageDesc(const char* name, glm::ivec2 size, VkFormat format) {
  vk::ImageDesc d;
  d.name = name;
  d.width = uint32_t(size.x);
  d.height = uint32_t(size.y);
  d.format = format;
  d.usage =
      VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  return d;
}

vk::Image storageImage(vk::Context& ctx, const char* name, glm::ivec2 size, VkFormat format) {
  return vk::Image(ctx, storageImageDesc(name, size, format));
}

vk::Image zeroedImage(vk::Context& ctx, vk::ImageDesc desc, vk::Use use) {
  desc.usage |= VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  vk::Image image(ctx, desc);
  VkCommandBuffer cmd = ctx.beginCommands();
  image.use(cmd, vk::Use::TransferDst);
  const VkClearColorValue zero{};
  const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &zero, 1, &range);
  image.use(cmd, use);
  ctx.submitAndWait(cmd);
  return image;
}

}  // namespace taa
