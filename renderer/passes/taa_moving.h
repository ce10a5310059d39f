// taa.moving: a second set of the resolve's float settings while the camera moves, blended
// smoothly (seed 000). The weight is a pure function of the case and the frame index.
#pragma once

#include "script/frame_state.h"
#include "spec/taa_spec.h"

namespace taa {

// How far the camera moved the image since the previous frame, in render pixels: the
// largest reprojection distance of five points (the screen centre and four points halfway
// to the corners) lying `depth` world units in front of the camera. 0 at frame 0 and at a cut.
float cameraSpeedPx(const script::FrameState& s, float depth);

// The weight of the moving settings: smoothstep(from_px, to_px, speed); 0 without taa.moving.
float movingWeight(const spec::TaaMovingSpec& moving, const script::FrameState& s);

// The float settings the resolve runs with this frame: still + (moving - still) * w, both
// after effectiveTaa; the still settings exactly when w is 0.
spec::TaaSpec blendMoving(const spec::TaaSpec& user, float w);

}  // namespace taa
