// Barriers batched per transition point: a pass gathers the transitions of every image it
// reads and writes (and any buffer dependencies) and records them in one
// vkCmdPipelineBarrier2, instead of one call per image.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>
#include <vector>

#include "vk/resources.h"

namespace taa::vk {

class BarrierBatch {
 public:
  // Adds `image`'s transition to `next`. An image given twice must be given the same
  // use (one barrier call cannot order two transitions of one image): std::logic_error.
  BarrierBatch& use(Image& image, Use next);
  // A global memory dependency, for buffers (storage, indirect arguments, transfers, host).
  BarrierBatch& memory(VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                       VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);
  // Records everything gathered in one call (none when nothing needs a barrier) and
  // empties the batch.
  void flush(VkCommandBuffer cmd);
  size_t pending() const { return images_.size() + memory_.size(); }

 private:
  std::vector<std::pair<const Image*, Use>> seen_;
  std::vector<VkImageMemoryBarrier2> images_;
  std::vector<VkMemoryBarrier2> memory_;
};

// One global memory barrier recorded at once (a batch of one).
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

}  // namespace taa::vk
