// The temporal resolve pass: owns the history (two images, ping-pong), builds one
// pipeline per history state from the case's settings, and records the dispatch.
#pragma once

#include <glm/vec2.hpp>

#include "common/shared.h"
#include "pass_plan.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// What the resolve reads this frame; optional inputs are null when the plan does not
// need them (a dummy texture is bound in their place).
struct TaaInputs {
  vk::Image* color = nullptr;  // render size: lit colour, or motion-blurred colour
  vk::Image* depth = nullptr;
  vk::Image* velocity = nullptr;
  vk::Image* ids = nullptr;
  vk::Image* normal = nullptr;
  vk::Image* prevDepth = nullptr;
  vk::Image* prevNormal = nullptr;
  vk::Image* prevIds = nullptr;
  vk::Image* prevVelocity = nullptr;
};

// The specialization constants of a case's resolve (exposed for the log and tests).
vk::SpecConstants taaSpecConstants(const spec::CaseSpec& spec, bool hasHistory);

gpu::TaaUniforms makeTaaUniforms(const spec::CaseSpec& spec, const script::FrameState& state,
                                 glm::ivec2 prevRenderSize);

class TaaResolvePass {
 public:
  TaaResolvePass(vk::Context& ctx, const spec::CaseSpec& spec, const PassPlan& plan);

  // Records the resolve for `state`; afterwards output() holds this frame's result.
  void record(VkCommandBuffer cmd, const script::FrameState& state, const TaaInputs& in);
  vk::Image& output() { return history_[current_]; }
  vk::Image* debugView() { return debug_ ? &debug_ : nullptr; }
  // Why each pixel's history went unused (TAA_REJECT_*); adaptive mode only.
  vk::Image* rejection() { return rejection_ ? &rejection_ : nullptr; }
  std::string describe() const;

 private:
  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  vk::Pipeline withHistory_;
  vk::Pipeline withoutHistory_;
  vk::Image history_[2];
  int current_ = 0;
  vk::Image debug_;
  vk::Image dummyFloat_;
  vk::Image dummyUint_;
  vk::Image dummyStorage_;  // debug target when the case has no debug view
  vk::Image dummyReject_;   // rejection target outside adaptive mode
  vk::Image rejection_;
  vk::Buffer uniforms_;
  vk::Sampler linear_;
  vk::Sampler point_;
  glm::ivec2 prevRenderSize_{0};
};

}  // namespace taa
