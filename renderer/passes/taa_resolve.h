// The temporal resolve pass: owns the history (two images, ping-pong), builds one
// pipeline per history state from the case's settings, and records the dispatch.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "common/shared.h"
#include "frame/pass_plan.h"
#include "passes/resolve_stage.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// The inputs the built-in resolve samples for a case's settings (its path's own and every
// setting's row), and the G-buffer targets they are.
ResolveInputSet taaResolveInputs(const spec::CaseSpec& spec);
GBufferNeeds taaResolveNeeds(const spec::CaseSpec& spec);

// One image the resolve samples and the bytes of one of its texels. Per pixel the resolve
// reads one texel of each (its neighbour taps hit the texture cache), the count seed 001
// gives as 128 bits (two colours, two velocities) and 64 with the speed in alpha.
struct ResolveRead {
  std::string name;
  uint32_t bytes;
};
std::vector<ResolveRead> taaResolveReads(const spec::CaseSpec& spec);
uint32_t taaResolveReadBytes(const spec::CaseSpec& spec);

// The specialization constants of a case's resolve (exposed for the log and tests).
vk::SpecConstants taaSpecConstants(const spec::CaseSpec& spec, bool hasHistory);

gpu::TaaUniforms makeTaaUniforms(const spec::CaseSpec& spec, const script::FrameState& state,
                                 glm::ivec2 prevRenderSize);

// Mono only: validation refuses stereo outside TSCMAA.
class TaaResolvePass final : public ResolveStage {
 public:
  TaaResolvePass(vk::Context& ctx, const spec::CaseSpec& spec, const PassPlan& plan);

  // Records the resolve for `eyeState` (eye 0); afterwards output() holds this frame's result.
  void record(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& eyeState, int eye,
              const ResolveInputs& in) override;
  vk::Image& output() override { return history_[current_]; }
  glm::ivec2 outputSize() const override;
  GBufferNeeds needs() const override { return taaResolveNeeds(spec_); }
  vk::Image* debugView() override { return debug_ ? &debug_ : nullptr; }
  // Why each pixel's history went unused (TAA_REJECT_*); adaptive mode only.
  vk::Image* rejection() override { return rejection_ ? &rejection_ : nullptr; }
  std::vector<std::string> describe() const override;

 private:
  void checkResolveReads(const ResolveInputs& in, ResolveInputSet reads) const;
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
