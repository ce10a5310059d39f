// The passes around the temporal resolve, built from three tables in post_chain.cpp
// when the case's plan enables them: before it (motion blur, which may pack speed into
// colour alpha for the resolve), following it with its outputs and the scene (adaptive
// tracing), and the image passes after it (sharpening, gradient or CAS, then FXAA).
// The renderer runs what the tables built; a new pass is one line in one table.
#pragma once

#include <glm/vec2.hpp>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "api/renderer.h"
#include "frame/draw_list.h"
#include "frame/gpu_scene.h"
#include "frame/pass_plan.h"
#include "passes/frame_pass.h"
#include "passes/resolve_stage.h"
#include "spec/case_spec.h"
#include "vk/resources.h"

namespace taa {

// What a table entry may build its pass from.
struct PassContext {
  vk::Context& ctx;
  const spec::CaseSpec& spec;
  const GpuScene& scene;
  const DrawList& firstFrame;  // frame 0's draws (the tracer sizes its geometry from them)
  const RenderOptions& options;
};

class PostChain {
 public:
  PostChain(const PassContext& context, const PassPlan& plan, glm::ivec2 maxRenderSize);
  ~PostChain();

  // Runs the passes that precede the resolve on one eye's `color`; returns the colour
  // the resolve reads (`color` itself when none runs).
  vk::Image& beforeResolve(const FrameView& eye, vk::Image& color);

  // Runs the passes that follow `resolve` on its output; returns the frame's image.
  vk::Image& followResolve(const FrameView& frame, ResolveStage& resolve, vk::Image& resolveInput);

  // Runs the passes that follow the resolve on `input`, whose top-left `size` pixels
  // are valid; returns the final image (the input itself when none runs).
  vk::Image& afterResolve(const FrameView& frame, vk::Image& input, glm::ivec2 size);

  // A view that replaces the output (the last pass's that has one), or null.
  vk::Image* debugView();
  // What the passes read back and report, as ResolveStage's methods of the same names.
  std::vector<StageCapture> captures();
  std::vector<std::pair<std::string, double>> stats() const;
  // The G-buffer targets its passes read beyond colour and depth.
  GBufferNeeds needs() const;
  std::vector<std::string> describe() const;

 private:
  struct Passes;
  std::unique_ptr<Passes> p_;
};

}  // namespace taa
