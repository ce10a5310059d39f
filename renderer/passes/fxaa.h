// FXAA 3.11 quality (shaders/fxaa.comp) with preset 39's search and the reference
// defaults for thresholds and sub-pixel removal.
#pragma once

#include <string>

#include "passes/image_pass.h"
#include "passes/post_filter.h"

namespace taa {

struct FxaaSettings {
  float edgeThreshold = 0.166f;      // minimum contrast relative to the local max luma
  float edgeThresholdMin = 0.0833f;  // absolute floor: darks below it are not processed
  float subpix = 0.75f;              // sub-pixel aliasing removal (0 off .. 1 softest)
};

class FxaaPass final : public ImagePass {
 public:
  // `masked`: filter only the pixels a segmentation mask marks ADAPTIVE_MASK_FXAA
  // (adaptive mode's out-of-history pixels) and copy the rest unchanged.
  explicit FxaaPass(vk::Context& ctx, const FxaaSettings& settings = {}, bool masked = false);
  void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size,
              vk::Image* mask) {
    filter_.record(cmd, input, output, size, mask);
  }
  void record(VkCommandBuffer cmd, vk::Image& input, vk::Image& output, glm::ivec2 size) override {
    filter_.record(cmd, input, output, size, nullptr);
  }
  std::string describe() const override;

 private:
  FxaaSettings settings_;
  bool masked_;
  PostFilter filter_;
};

}  // namespace taa
