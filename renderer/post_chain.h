// The passes around the temporal resolve, built only when the case enables them:
// motion blur before it (it may pack speed into colour alpha for the resolve), then the
// image passes of post_chain.cpp's table after it (sharpening, gradient or CAS, then FXAA).
#pragma once

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <vector>

#include "pass_plan.h"
#include "passes/gbuffer.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/resources.h"
#include "vk/timestamps.h"

namespace taa {

class PostChain {
 public:
  PostChain(vk::Context& ctx, const spec::CaseSpec& spec, const PassPlan& plan, glm::ivec2 maxRenderSize);
  ~PostChain();

  // Runs the passes that precede the resolve; returns the colour the resolve reads
  // (the G-buffer's colour itself when none runs).
  vk::Image& beforeResolve(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& state,
                           GBufferTargets& targets);

  // Runs the passes that follow the resolve on `input`, whose top-left `size` pixels
  // are valid; returns the final image (the input itself when none runs).
  vk::Image& afterResolve(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& state, vk::Image& input,
                          glm::ivec2 size);

  // The G-buffer targets its passes read beyond colour and depth.
  GBufferNeeds needs() const;
  std::vector<std::string> describe() const;

 private:
  struct Passes;
  std::unique_ptr<Passes> p_;
};

}  // namespace taa
