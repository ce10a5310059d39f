// The supersampled ground truth: the frame's scene at the same instant, without
// TAA or jitter, rendered N times at sub-pixel offsets and averaged in float32.
#pragma once

#include <glm/vec2.hpp>
#include <vector>

#include "frame/draw_list.h"
#include "frame/gpu_scene.h"
#include "passes/gbuffer.h"
#include "passes/shadow.h"
#include "passes/still_image.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// Sub-pixel offsets in pixels, each in (-0.5, 0.5): a regular m x m grid of cell
// centres when `count` is a square, else the Hammersley set (i + 0.5) / N against
// the base-2 radical inverse. Both are stratified and a pure function of `count`.
std::vector<glm::vec2> referenceOffsets(int count);

class ReferencePass {
 public:
  // `shadow`: the frame's shadow atlas (lighting.shadows), which the reference samples too.
  // `still` (debug.image): each sub-sample is the still image's nearest texel, so the
  // reference is the full-size image itself.
  ReferencePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
                ShadowPass* shadow = nullptr, StillImagePass* still = nullptr);

  // Records every sub-sample render and the average for this frame, seen from `eye`
  // (stereo TSCMAA: each eye fills its half of the side-by-side output).
  void record(VkCommandBuffer cmd, const script::FrameState& state, const DrawList& draws,
              VkBuffer instances, const ShadowCascades& shadows = {}, int eye = 0);
  vk::Image& output() { return accum_; }
  int samples() const { return int(offsets_.size()); }

 private:
  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  std::vector<glm::vec2> offsets_;
  GBufferConfig config_;
  GBufferTargets targets_;
  GBufferPass gbuffer_;
  vk::Pipeline accumulate_;
  vk::Image accum_;
  vk::Buffer uniforms_;  // one FrameUniforms block per sub-sample and eye
  VkDeviceSize stride_ = 0;
  vk::Sampler point_;
  StillImagePass* still_ = nullptr;
};

}  // namespace taa
