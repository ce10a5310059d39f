// What a run asks of the renderer beyond the case: the images it reads back beside the
// output, and whether every frame's output is hashed.
#pragma once

#include <string>

#include "api/captures.h"

namespace taa {

class ReferenceCache;

struct RenderOptions {
  // The images read back beside the output of every frame whose images are read (see
  // api/captures.h). Capture::Reference renders the supersampled reference for those frames
  // (reference.samples extra scene renders each), nothing more.
  CaptureSet captures;
  // Read back and hash the output of every frame, not only of those whose images are read:
  // goldens record each frame's pixel hash, so a frame no golden image covers is still
  // checked. Sets FrameRecord::color and colorSha256 for every frame; aux buffers, captures
  // and the reference still come only with readImages.
  bool hashEveryFrame = false;
  // Reference frames shared across the renderers of a run (api/reference_cache.h), used
  // when both are set: `referenceKey` names everything the case gives the reference pass
  // (the harness's run::referenceKey), the renderer adds each frame's own inputs.
  ReferenceCache* referenceCache = nullptr;
  std::string referenceKey;
};

}  // namespace taa
