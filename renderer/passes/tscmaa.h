// TSCMAA (taa.mode tscmaa), one eye at a time: luma edge detection building an edge
// list and a TAA list (shaders/tscmaa_edges.comp), CMAA on the edge list
// (tscmaa_cmaa.comp) and TAA on the TAA list (tscmaa_taa.comp), both dispatched
// indirectly so their cost follows the edge count. Each eye keeps its own history;
// output() holds the eyes side by side.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "common/shared.h"
#include "passes/resolve_stage.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"
#include "vk/timestamps.h"

namespace taa {

// One eye's list headers of the last submitted frame.
struct TscmaaCounts {
  gpu::EdgeListHeader edges{};  // groupsX is the CMAA dispatch, count the edge pixels
  gpu::EdgeListHeader taa{};    // the same for the TAA pass
};

gpu::TscmaaUniforms makeTscmaaUniforms(const spec::TscmaaSpec& t, glm::ivec2 eyeSize, int eye);

// "tscmaa_edges" and "tscmaa_taa_pixels" summed over the eyes.
std::vector<std::pair<std::string, double>> tscmaaCounters(const std::vector<TscmaaCounts>& counts);

class TscmaaPass final : public ResolveStage {
 public:
  // With Capture::Current in `captures` it keeps a side-by-side copy of each eye's input
  // colour to read back; the CMAA image and the edge mask are always there to read.
  TscmaaPass(vk::Context& ctx, const spec::CaseSpec& spec, CaptureSet captures = {});
  ~TscmaaPass() override;
  TscmaaPass(const TscmaaPass&) = delete;
  TscmaaPass& operator=(const TscmaaPass&) = delete;

  // Records the three steps for `eye` from its colour and depth (eye size, top-left).
  // Call for every eye of a frame, in order.
  void record(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& eyeState, int eye,
              const ResolveInputs& in) override;

  vk::Image& output() override;  // this frame's result, eyes side by side
  glm::ivec2 outputSize() const override;
  GBufferNeeds needs() const override { return {.depth = true}; }  // and colour
  vk::Image& cmaa() { return cmaa_; }  // the CMAA result, eyes side by side
  vk::Image& mask() { return mask_; }  // R32_UINT TSCMAA_EDGE_* / TSCMAA_TAA bits
  vk::Image* input() { return input_ ? &input_ : nullptr; }
  std::vector<StageCapture> captures() override;
  std::vector<TscmaaCounts> counts() const;  // per eye, valid once the frame completed
  std::vector<std::pair<std::string, double>> stats() const override;
  std::vector<std::string> describe() const override;

 private:
  struct Eye;
  void detectEdges(VkCommandBuffer cmd, Eye& e, vk::Image& color);
  void antialias(VkCommandBuffer cmd, Eye& e, vk::Image& color);
  void temporal(VkCommandBuffer cmd, Eye& e, vk::Image& depth);

  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  glm::ivec2 eyeSize_;
  std::vector<Eye> eyes_;
  vk::Pipeline edges_, cmaaPipeline_, taa_;
  vk::Image mask_, cmaa_, input_, sideBySide_;
  vk::Buffer uniforms_;  // per eye: TscmaaUniforms, then TaaUniforms, each slot aligned
  vk::Buffer readback_;  // per eye: the two list headers
  VkDeviceSize stride_ = 0;
  vk::Sampler point_, linear_;
  int current_ = 0;  // history index written this frame
};

}  // namespace taa
