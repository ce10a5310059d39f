// Stereo for TSCMAA (tscmaa.eyes 2): two parallel cameras half the eye separation to
// either side of the case's camera, rendered one after the other and shown side by
// side (left eye on the left), so the output is 2 x render.width wide.
#pragma once

#include <glm/vec2.hpp>

#include "script/frame_state.h"
#include "spec/case_spec.h"

namespace taa {

// 2 for a stereo TSCMAA case, else 1.
int eyeCount(const spec::CaseSpec& spec);

// The final image's size: render.width x eyes by render.height.
glm::ivec2 outputSize(const spec::CaseSpec& spec);

// The frame seen from eye `eye` (0 left, 1 right) of `eyes`: camera and previous camera
// moved by -+ separation / 2 along their right axes; projection, jitter and movers as
// they are. With one eye, the frame itself.
script::FrameState eyeFrameState(const script::FrameState& frame, int eye, int eyes,
                                 float separation);

}  // namespace taa
