// What the G-buffer pass draws this frame: per-instance transforms (current and
// previous, for velocity) and the draws, opaque first, blended back to front.
// Pure CPU work, a function of the scene and the frame state.
#pragma once

#include <cstdint>
#include <vector>

#include "common/shared.h"
#include "scene/scene.h"
#include "script/frame_state.h"

namespace taa {

struct Draw {
  uint32_t instance = 0;
  int mesh = 0;
  int primitive = 0;
};

struct DrawList {
  std::vector<gpu::InstanceData> instances;
  std::vector<Draw> opaque;  // opaque and alpha-tested
  std::vector<Draw> blended;  // sorted far to near
};

DrawList buildDrawList(const scene::Scene& scene, const script::FrameState& state);

}  // namespace taa
