// Which passes and buffers a case needs, derived from its settings alone: nothing
// is allocated, compiled or run that the case does not use. The G-buffer targets follow
// from what the built passes say they read (GBufferNeeds), never from a list kept here.
#pragma once

#include <glm/vec2.hpp>
#include <string>
#include <vector>

#include "passes/gbuffer.h"
#include "passes/gbuffer_needs.h"
#include "spec/case_spec.h"

namespace taa {

struct PassPlan {
  bool deferred = false;
  int msaa = 1;  // samples per pixel, resolved within the raster pass
  // A temporal resolve runs (which one is makeResolveStage's choice, resolve_factory.cpp).
  bool taa = false;
  // Segmentation, tracing and masked FXAA after the resolve (taa.mode adaptive).
  bool adaptive = false;
  // Passes around the resolve.
  bool motionBlur = false;
  bool sharpen = false;
  bool cas = false;
  bool fxaa = false;
  bool debugView = false;
  // Targets read by no pass but by the case's own output (output.aux) or a capture the
  // harness asks for (set by the renderer), and the normals deferred lighting reads.
  GBufferNeeds own;

  std::vector<std::string> describe() const;
};

PassPlan planPasses(const spec::CaseSpec& spec);

// The G-buffer of a run at `maxRenderSize`: the targets `passes` (the union of the built
// passes' needs) and the plan's own outputs read.
GBufferConfig planGBuffer(const PassPlan& plan, const GBufferNeeds& passes,
                          glm::ivec2 maxRenderSize);

}  // namespace taa
