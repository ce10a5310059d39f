// Still-image upsampling (debug.image): writes the case's image, sampled at each render
// pixel's jittered centre, over the G-buffer's colour, so the resolve upsamples a known
// high-resolution image; the reference pass samples it at output size.
#pragma once

#include <glm/vec2.hpp>

#include "core/image.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

class StillImagePass {
 public:
  StillImagePass(vk::Context& ctx, const Image& image);

  // Fills the top-left `size` of `color` with the image seen through a frame of that size
  // moved by `jitter` render pixels; `nearest` picks the sampler (else bilinear).
  void record(VkCommandBuffer cmd, vk::Image& color, glm::ivec2 size, glm::vec2 jitter,
              bool nearest);

 private:
  vk::Context& ctx_;
  vk::Image image_;
  vk::Pipeline pipeline_;
  vk::Sampler linear_;
  vk::Sampler nearest_;
};

}  // namespace taa
