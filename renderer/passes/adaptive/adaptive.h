// Adaptive ray tracing (Marrs et al.), run after the full resolve when taa.mode is
// adaptive: segmentation, then tracing of the marked pixels into the resolve's output
// (so they reach the history too), then FXAA on the out-of-history pixels left
// untraced (output only: the history keeps the resolve's value there).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/frame_record.h"
#include "frame/gpu_scene.h"
#include "passes/adaptive/segmentation.h"
#include "passes/adaptive/trace.h"
#include "passes/frame_pass.h"
#include "passes/fxaa.h"
#include "vk/timestamps.h"

namespace taa {

struct AdaptiveFrame {
  const script::FrameState* state = nullptr;
  const DrawList* draws = nullptr;
  VkBuffer frameUniforms = VK_NULL_HANDLE;
  float lodBias = 0.0f;
};

class AdaptivePass final : public ResolveFollower {
 public:
  // With Capture::Resolved in `captures` it keeps a copy of the resolve's output before
  // tracing to read back (for the adaptive_unmarked invariant and tests).
  AdaptivePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
               const DrawList& firstFrame, CaptureSet captures);

  // `resolved` is the resolve's output; returns the frame's output.
  vk::Image& record(VkCommandBuffer cmd, vk::GpuTimer& timer, const AdaptiveFrame& frame,
                    const SegmentationInputs& in, vk::Image& resolved);
  // The same from the frame, the resolve (its rejection mask) and the colour it read.
  vk::Image& record(const FrameView& frame, ResolveStage& resolve, vk::Image& resolveInput,
                    vk::Image& resolved) override;
  vk::Image* debugView() override { return segmentation_.debugView(); }
  // Segmentation compares material ids and normal derivatives.
  GBufferNeeds needs() const override { return {.normal = true, .ids = true}; }

  // After the frame completed: the shares of pixels traced and FXAA'd.
  std::vector<std::pair<std::string, double>> stats() const override;
  // "taa_resolve" (before tracing) and "segmentation" (the ADAPTIVE_MASK_* value per
  // pixel), when capturing; read back at render size with the frame.
  std::vector<StageCapture> captures() override;
  std::vector<std::string> describe() const override;

 private:
  const spec::CaseSpec& spec_;
  SegmentationPass segmentation_;
  TracePass trace_;
  std::unique_ptr<FxaaPass> fxaa_;
  vk::Image filtered_;  // FXAA output, in the history's format
  vk::Image beforeTrace_;
  glm::ivec2 lastSize_{0};
};

}  // namespace taa
