// Runs the real TaaResolvePass on synthetic inputs (no scene, no raster pass), so a test can
// set exactly what the resolve sees: current colour, history, depth and a velocity.
#pragma once

#include <glm/vec2.hpp>

#include "core/image.h"
#include "spec/case_spec.h"

namespace taa::test {

struct SyntheticResolve {
  Image current;               // RGB(A), the case's render size
  Image history;               // RGB(A), the case's output size
  glm::vec2 velocityPx{0.0f};  // constant over the frame, render pixels
  float depth = 0.5f;          // constant reversed-Z depth
};

struct GpuResolveResult {
  Image output;   // the frame under test, as stored (history format)
  Image history;  // the history the pass really held when the frame ran
  Image current;  // the current colour as uploaded (RGBA16F, like the renderer's target)
  glm::vec2 velocityPx{0.0f};  // the velocity as uploaded (RG16F)
};

// The history is seeded by a no-history frame whose input colour is `in.history` (such a
// frame stores its input as the new history), then the frame under test runs with history.
// Frame states are script::frameState of frames 0 and 1, with no jitter.
GpuResolveResult gpuResolve(const spec::CaseSpec& spec, const SyntheticResolve& in);

}  // namespace taa::test
