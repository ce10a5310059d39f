// Adaptive ray tracing's segmentation pass (shaders/adaptive_segmentation.comp): owns
// the mask, the per-pixel history counter and the traced/FXAA pixel counts.
#pragma once

#include <glm/vec2.hpp>

#include "common/shared.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// What the segmentation reads; all at output size (adaptive mode does not resample).
struct SegmentationInputs {
  vk::Image* color = nullptr;  // the resolve's input colour
  vk::Image* depth = nullptr;
  vk::Image* normal = nullptr;
  vk::Image* ids = nullptr;
  vk::Image* rejection = nullptr;  // TAA_REJECT_* from the resolve
  vk::Image* resolved = nullptr;   // the resolve's output (debug view background)
};

gpu::SegmentationUniforms makeSegmentationUniforms(const spec::CaseSpec& spec,
                                                   const script::FrameState& state);

class SegmentationPass {
 public:
  SegmentationPass(vk::Context& ctx, const spec::CaseSpec& spec);

  void record(VkCommandBuffer cmd, const script::FrameState& state, const SegmentationInputs& in);
  vk::Image& mask() { return mask_; }
  vk::Image* debugView() { return debug_ ? &debug_ : nullptr; }
  // This frame's counts; valid once the frame's commands completed.
  gpu::AdaptiveCounts counts() const;

 private:
  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  vk::Pipeline withHistory_;
  vk::Pipeline withoutHistory_;
  vk::Image mask_;
  vk::Image counter_;
  vk::Image debug_;
  vk::Image noDebug_;
  vk::Buffer uniforms_;
  vk::Buffer counts_;
  vk::Sampler point_;
};

}  // namespace taa
