// The 5-tap gradient sharpener (shaders/sharpen.comp): out = c + amount * (4c - n -
// s - e - w) / 4, clamped to [0, half max].
#pragma once

#include <string>

#include "passes/image_pass.h"
#include "passes/post_filter.h"

namespace taa {

class SharpenPass final : public ImagePass {
 public:
  SharpenPass(vk::Context& ctx, float amount);
  void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size) override {
    filter_.record(cmd, input, output, size);
  }
  std::string describe() const override;

 private:
  float amount_;
  PostFilter filter_;
};

}  // namespace taa
