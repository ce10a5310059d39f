// Which passes and buffers a case needs, derived from its settings alone: nothing
// is allocated, compiled or run that the case does not use.
#pragma once

#include <string>
#include <vector>

#include "spec/case_spec.h"

namespace taa {

struct PassPlan {
  // Raster targets beyond colour and depth.
  bool velocity = false;
  bool normal = false;
  bool ids = false;
  bool deferred = false;
  // Temporal resolve and the previous frame's G-buffer it reads.
  bool taa = false;
  bool tscmaa = false;  // the TSCMAA passes replace the resolve
  bool userResolve = false;  // a user's shader (taa.shader) replaces the resolve
  bool prevDepth = false;
  bool prevNormal = false;
  bool prevIds = false;
  bool prevVelocity = false;
  // Segmentation, tracing and masked FXAA after the resolve (taa.mode adaptive).
  bool adaptive = false;
  // Passes around the resolve.
  bool motionBlur = false;
  bool sharpen = false;
  bool cas = false;
  bool fxaa = false;
  bool debugView = false;

  std::vector<std::string> describe() const;
};

PassPlan planPasses(const spec::CaseSpec& spec);

}  // namespace taa
