#include "vk/transfer.h"

#include <algorithm>
#include <cstring>

#include "vk/context.h"

namespace taa::vk {

Buffer uploadBuffer(Context& ctx, const void* data, VkDeviceSize size, VkBufferUsageFlags usage) {
  size = std::max<VkDeviceSize>(size, 4);  // zero-sized buffers are invalid; keep a word
  Buffer staging(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::memset(staging.mapped(), 0, size);
  if (data) std::memcpy(staging.mapped(), data, size);
  Buffer out(ctx, size, usage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, false);
  VkCommandBuffer cmd = ctx.beginCommands();
  VkBufferCopy region{0, 0, size};
  vkCmdCopyBuffer(cmd, staging.handle(), out.handle(), 1, &region);
  ctx.submitAndWait(cmd);
  return out;
}

void uploadImage(Context& ctx, Image& image, const std::vector<const void*>& levels) {
  const auto& d = image.desc();
  const uint32_t texel = formatBytes(d.format);
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize total = 0;
  for (uint32_t m = 0; m < levels.size(); ++m) {
    offsets.push_back(total);
    const VkDeviceSize w = std::max(1u, d.width >> m), h = std::max(1u, d.height >> m);
    total += w * h * texel;
  }
  Buffer staging(ctx, total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
  std::vector<VkBufferImageCopy> regions;
  for (uint32_t m = 0; m < levels.size(); ++m) {
    const uint32_t w = std::max(1u, d.width >> m), h = std::max(1u, d.height >> m);
    std::memcpy(static_cast<uint8_t*>(staging.mapped()) + offsets[m], levels[m], size_t(w) * h * texel);
    VkBufferImageCopy r{};
    r.bufferOffset = offsets[m];
    r.imageSubresource = {image.aspect(), m, 0, 1};
    r.imageExtent = {w, h, 1};
    regions.push_back(r);
  }
  VkCommandBuffer cmd = ctx.beginCommands();
  image.use(cmd, Use::TransferDst);
  vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         uint32_t(regions.size()), regions.data());
  image.use(cmd, Use::SampledGraphics);
  ctx.submitAndWait(cmd);
}

}  // namespace taa::vk
