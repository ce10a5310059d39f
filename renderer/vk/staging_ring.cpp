#include "vk/staging_ring.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "vk/barrier.h"
#include "vk/context.h"

namespace taa::vk {

namespace {

// Copy offsets stay aligned for any texel size the renderer reads (up to RGBA32F).
constexpr VkDeviceSize kStagingAlign = 16;

Buffer stagingBuffer(Context& ctx, VkDeviceSize bytes) {
  return Buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
}

}  // namespace

StagingRing::StagingRing(Context& ctx, VkDeviceSize initialBytes) : ctx_(ctx) {
  if (initialBytes) {
    buffers_.push_back(stagingBuffer(ctx, initialBytes));
    ++created_;
  }
}

StagingRing::Slot StagingRing::allocate(VkDeviceSize bytes) {
  const VkDeviceSize start = (head_ + kStagingAlign - 1) / kStagingAlign * kStagingAlign;
  if (buffers_.empty() || start + bytes > buffers_.back().size()) {
    // Copies already recorded point into the current buffer: it stays until reset().
    const VkDeviceSize grown = std::max(bytes, buffers_.empty() ? 0 : 2 * buffers_.back().size());
    buffers_.push_back(stagingBuffer(ctx_, grown));
    ++created_;
    head_ = bytes;
    return {buffers_.size() - 1, 0, bytes};
  }
  head_ = start + bytes;
  return {buffers_.size() - 1, start, bytes};
}

StagingRing::Slot StagingRing::copyImage(VkCommandBuffer cmd, const Image& image, uint32_t layer) {
  if (image.lastUse() != Use::TransferSrc)
    throw std::logic_error("StagingRing: image '" + image.desc().name +
                           "' is read back without its transition to TransferSrc");
  const auto& d = image.desc();
  const Slot slot = allocate(VkDeviceSize(d.width) * d.height * formatBytes(d.format));
  VkBufferImageCopy r{};
  r.bufferOffset = slot.offset;
  r.imageSubresource = {image.aspect(), 0, layer, 1};
  r.imageExtent = {d.width, d.height, 1};
  vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                         buffers_[slot.buffer].handle(), 1, &r);
  return slot;
}

void StagingRing::finishCopies(VkCommandBuffer cmd) const {
  memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
}

const uint8_t* StagingRing::data(const Slot& slot) const {
  if (slot.buffer >= buffers_.size() || slot.offset + slot.bytes > buffers_[slot.buffer].size())
    throw std::logic_error("StagingRing: a slot of an earlier batch was read after reset()");
  return static_cast<const uint8_t*>(buffers_[slot.buffer].mapped()) + slot.offset;
}

void StagingRing::reset() {
  head_ = 0;
  if (buffers_.size() <= 1) return;
  // The batch needed all of them: one buffer of their total serves the next alike.
  const VkDeviceSize total =
      std::accumulate(buffers_.begin(), buffers_.end(), VkDeviceSize(0),
                      [](VkDeviceSize sum, const Buffer& b) { return sum + b.size(); });
  buffers_.clear();
  buffers_.push_back(stagingBuffer(ctx_, total));
  ++created_;
}

VkDeviceSize StagingRing::capacity() const {
  return buffers_.empty() ? 0 : buffers_.back().size();
}

std::vector<uint8_t> readImage(Context& ctx, Image& image, uint32_t layer) {
  StagingRing ring(ctx);
  VkCommandBuffer cmd = ctx.beginCommands();
  const Use before = image.lastUse();
  image.use(cmd, Use::TransferSrc);
  const StagingRing::Slot slot = ring.copyImage(cmd, image, layer);
  ring.finishCopies(cmd);
  if (before != Use::Undefined) image.use(cmd, before);
  ctx.submitAndWait(cmd);
  const uint8_t* p = ring.data(slot);
  return std::vector<uint8_t>(p, p + slot.bytes);
}

}  // namespace taa::vk
