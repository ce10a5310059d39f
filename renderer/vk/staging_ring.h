// One host-visible staging buffer that every readback copies into, reused frame after
// frame instead of a fresh buffer per readback (niagara's scratch buffer). Copies are
// recorded into the frame's own command buffer and come back with its one submit; the
// ring restarts at the front once those commands completed (reset()). It grows only when
// one batch needs more than it holds, and then settles at that size.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "vk/resources.h"

namespace taa::vk {

class Context;

class StagingRing {
 public:
  explicit StagingRing(Context& ctx, VkDeviceSize initialBytes = 0);

  struct Slot {
    size_t buffer = 0;  // index into the buffers of this batch
    VkDeviceSize offset = 0;
    VkDeviceSize bytes = 0;
  };

  // Records the copy of mip 0, `layer` of `image` (tightly packed) into the ring. The
  // image must already be in its TransferSrc use (batch the transitions of all images
  // read at one point): std::logic_error otherwise.
  Slot copyImage(VkCommandBuffer cmd, const Image& image, uint32_t layer = 0);
  // Records the host-read dependency of every copy so far; call once after the copies.
  void finishCopies(VkCommandBuffer cmd) const;
  // The slot's bytes, once the commands that copied them completed.
  const uint8_t* data(const Slot& slot) const;
  // Frees every slot (their commands completed). A batch that outgrew the ring leaves
  // one buffer of the size it needed.
  void reset();

  VkDeviceSize capacity() const;
  int buffersCreated() const { return created_; }

 private:
  Slot allocate(VkDeviceSize bytes);
  Context& ctx_;
  std::vector<Buffer> buffers_;  // more than one only while a batch outgrows the first
  VkDeviceSize head_ = 0;        // next free byte of buffers_.back()
  int created_ = 0;
};

// Copies one array layer of mip 0 to the host, tightly packed, through a ring of its own
// (one submit and wait); the image returns to its previous use. For tools and tests; the
// renderer reads frames through its StagingRing.
std::vector<uint8_t> readImage(Context& ctx, Image& image, uint32_t layer = 0);

}  // namespace taa::vk
