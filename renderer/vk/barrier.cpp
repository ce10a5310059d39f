#include "vk/barrier.h"

#include <stdexcept>

namespace taa::vk {

BarrierBatch& BarrierBatch::use(Image& image, Use next) {
  for (const auto& [img, use] : seen_)
    if (img == &image) {
      if (use != next)
        throw std::logic_error("image '" + image.desc().name +
                               "' is given two different uses at one transition point");
      return *this;
    }
  seen_.emplace_back(&image, next);
  if (const auto b = image.transition(next)) images_.push_back(*b);
  return *this;
}

BarrierBatch& BarrierBatch::memory(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStage;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStage;
  b.dstAccessMask = dstAccess;
  memory_.push_back(b);
  return *this;
}

void BarrierBatch::flush(VkCommandBuffer cmd) {
  if (!images_.empty() || !memory_.empty()) {
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.memoryBarrierCount = uint32_t(memory_.size());
    dep.pMemoryBarriers = memory_.data();
    dep.imageMemoryBarrierCount = uint32_t(images_.size());
    dep.pImageMemoryBarriers = images_.data();
    vkCmdPipelineBarrier2(cmd, &dep);
  }
  seen_.clear();
  images_.clear();
  memory_.clear();
}

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  BarrierBatch().memory(srcStage, srcAccess, dstStage, dstAccess).flush(cmd);
}

}  // namespace taa::vk
