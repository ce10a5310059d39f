// Contrast Adaptive Sharpening (shaders/cas.comp): the negative lobe of a 5-tap
// cross adapts to the 3x3 neighbourhood's headroom; sharpness (post.sharpen_amount)
// moves its peak from -1/8 (0) to -1/5 (1).
#pragma once

#include <string>

#include "passes/image_pass.h"
#include "passes/post_filter.h"

namespace taa {

// -1 / mix(8, 5, sharpness): the lobe weight at full amplitude.
float casPeak(float sharpness);

class CasPass final : public ImagePass {
 public:
  CasPass(vk::Context& ctx, float sharpness);
  void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size) override {
    filter_.record(cmd, input, output, size);
  }
  std::string describe() const override;

 private:
  float sharpness_;
  PostFilter filter_;
};

}  // namespace taa
