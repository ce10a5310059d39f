// Adaptive ray tracing's trace pass (shaders/adaptive_trace.comp): owns the scene's
// BVHs, triangles and materials in storage buffers and traces the marked pixels into
// the resolve's output.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "common/shared.h"
#include "frame/draw_list.h"
#include "frame/gpu_scene.h"
#include "script/frame_state.h"
#include "spec/case_spec.h"
#include "vk/pipeline.h"
#include "vk/resources.h"

namespace taa {

// Sample positions (pixels from the pixel centre) of `samples` traced rays: the
// Hammersley set ((i + 0.5) / N against the base-2 radical inverse), stratified in x
// and in y alike (no two rays share a row or a column), so that a thin near-horizontal
// or near-vertical wire's coverage is sampled at N offsets rather than at sqrt(N) as
// a grid would. A single ray goes through the pixel centre.
std::vector<glm::vec2> traceOffsets(int samples);

gpu::TraceUniforms makeTraceUniforms(const spec::CaseSpec& spec, const script::FrameState& state,
                                     float lodBias, uint32_t staticRoot, uint32_t moverRoot);

class TracePass {
 public:
  // `firstFrame` supplies the static world's instances (they never move).
  TracePass(vk::Context& ctx, const spec::CaseSpec& spec, const GpuScene& scene,
            const DrawList& firstFrame);

  // Re-poses the movers' triangles and rebuilds their BVH, then traces every pixel
  // `mask` marks into `target` (the resolve's output).
  void record(VkCommandBuffer cmd, const script::FrameState& state, const DrawList& draws,
              VkBuffer frameUniforms, float lodBias, vk::Image& mask, vk::Image& target);
  std::string describe() const;

 private:
  vk::Context& ctx_;
  const spec::CaseSpec& spec_;
  const GpuScene& scene_;
  vk::Pipeline pipeline_;
  uint32_t staticNodes_ = 0, staticTriangles_ = 0, moverTriangles_ = 0;
  uint32_t textureSlots_ = 1;  // the spec constant TRACE_SPEC_TEXTURE_SLOTS
  vk::Buffer nodes_, triangles_, shading_, materials_, uniforms_;
  std::vector<VkImageView> views_;
  std::vector<VkSampler> samplers_;
  vk::Sampler point_;
};

}  // namespace taa
