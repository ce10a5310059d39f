// The sky's velocity for a direction that was behind last frame's camera: there is no previous
// pixel, so the G-buffer says no motion rather than the mirrored pixel a projection with a
// negative w gives. Only a turn of more than about 90 degrees less half the field of view in
// one frame reaches it, which no case makes.
#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu.h"

namespace taa::sky_velocity_test {

TEST(SkyVelocity, ADirectionBehindLastFramesCameraHasNoMotion) {
  // One frame a second turning 180 degrees a second: frame 1 looks the other way.
  const auto spec = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"fps": 1, "frames": 2},
    "camera": {"rotate": {"yaw_deg_per_s": 180}},
    "output": {"frames": [1], "aux": ["depth", "velocity"]}
  })", "sky_velocity");
  const auto frames = test::renderCase(spec);
  const Image& depth = test::auxImage(frames[1], "depth");
  const Image& velocity = test::capturedImage(frames[1], Capture::Velocity);
  int sky = 0, moving = 0;
  for (int y = 0; y < depth.height; ++y)
    for (int x = 0; x < depth.width; ++x) {
      if (depth.at(x, y) != 0.0f) continue;  // reversed Z: the sky is at 0
      ++sky;
      moving += velocity.at(x, y, 0) != 0.0f || velocity.at(x, y, 1) != 0.0f;
    }
  EXPECT_GT(sky, 1000) << "the view must show sky";
  EXPECT_EQ(moving, 0) << "of " << sky << " sky pixels";
}

}  // namespace taa::sky_velocity_test
