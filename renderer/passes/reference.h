// The supersampled ground truth: the frame's scene at the same instant, without
// TAA or jitter, rendered N times at sub-pixel offsets and averaged in float32.
#pragma once

#include <glm/vec2.hpp>
#include <string>
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

  // Writes this frame's sub-sample uniforms seen from `eye` (stereo TSCMAA: each eye fills
  // its half of the side-by-side output); record() draws with them.
  void prepare(const script::FrameState& state, const ShadowCascades& shadows = {}, int eye = 0);
  // Records every sub-sample render of `eye` and their average.
  void record(VkCommandBuffer cmd, const DrawList& draws, VkBuffer instances, int eye = 0);
  // What this frame's reference is a function of, once every eye is prepared: `caseKey` (what
  // the case gives the pass: scene, shading, size, samples; RenderOptions::referenceKey), the
  // sub-samples' uniforms, the draws, instances and deformed vertices, and the shadow cascades),
  // and the SPIR-V the pass and the passes it reads run (setShaders).
  std::string frameKey(const std::string& caseKey, const DrawList& draws,
                       const ShadowCascades& shadows) const;
  // The shaders (names in shaderFolder()) whose code reaches the reference: its own and those
  // of the shadow and still-image passes it reads. Their SPIR-V bytes join frameKey, so a
  // reference kept on disk is not read after an edit of one; an edit of the resolve's is.
  void setShaders(const std::vector<std::string>& names);
  const std::vector<std::string>& shaders() const { return shaderNames_; }
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
  std::vector<std::string> shaderNames_;
  std::string shaderDigest_;  // SHA-256 over shaderNames_' names and SPIR-V
};

}  // namespace taa
