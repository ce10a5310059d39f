// The per-frame uniform block, derived from the frame state and the lighting spec.
#pragma once

#include "common/shared.h"
#include "script/frame_state.h"
#include "spec/scene_spec.h"

namespace taa {

gpu::FrameUniforms makeFrameUniforms(const script::FrameState& state, const spec::LightingSpec& lighting);

}  // namespace taa
