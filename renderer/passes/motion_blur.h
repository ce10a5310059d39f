// Motion blur before the resolve (shaders/motion_blur.comp): a centred box filter
// along each pixel's own velocity, depth-aware, optionally packing the pixel's speed
// into alpha for the resolve (taa.velocity_in_alpha).
#pragma once

#include <glm/vec2.hpp>
#include <string>

#include "passes/frame_pass.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

struct MotionBlurSettings {
  int samples = 8;               // taps along the velocity, >= 2
  float scale = 1.0f;            // fraction of the frame's motion the blur spans
  bool velocityInAlpha = false;  // alpha = speed in render pixels, else 1
  float depthTolerance = 0.05f;  // taps nearer than the centre by more (relative) are ignored
};

class MotionBlurPass final : public BeforeResolvePass {
 public:
  MotionBlurPass(vk::Context& ctx, const MotionBlurSettings& settings);

  // The colour a frame's resolve reads: `input` blurred along the G-buffer's velocity.
  void record(const FrameView& frame, vk::Image& input, vk::Image& output) override;
  GBufferNeeds needs() const override { return {.velocity = true}; }

  // Blurs the top-left `size` pixels of `color` along `velocity` (RG, render pixels,
  // current minus previous position) into `output`; `depth` is reversed Z.
  void record(VkCommandBuffer cmd, vk::Image& color, vk::Image& velocity, vk::Image& depth,
              vk::Image& output, glm::ivec2 size);
  std::string describe() const override;

 private:
  vk::Context& ctx_;
  MotionBlurSettings settings_;
  vk::Pipeline pipeline_;
  vk::Sampler point_;
};

}  // namespace taa
