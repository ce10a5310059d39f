// History validation: off-screen history is replaced by the current frame; depth culling,
// geometric consistency and dynamic anti-ghosting each clear the trail a mover leaves (with
// rectification off, so it cannot mask them); rejection_alpha acts on rejected pixels only.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

// A fast pan (~3.5 px per frame) turning left: new content enters at the left border.
const char* kRejectionPan = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"rotate": {"yaw_deg_per_s": 120}},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 6}
})";

RenderOptions currentAndVelocity() {
  RenderOptions o;
  o.captures |= {Capture::Current};
  o.captures |= {Capture::Velocity};
  return o;
}

// Pixels whose own motion puts last frame's position more than 1.5 px off the left or right
// edge: no neighbour's velocity can bring them back on screen.
test::Mask revealed(const FrameRecord& r) {
  const Image& v = test::capturedImage(r, Capture::Velocity);
  return test::maskWhere(v.width, v.height, [&](int x, int y) {
    const float prevX = x + 0.5f - v.at(x, y, 0);
    return prevX < -1.5f || prevX > v.width + 1.5f;
  });
}

TEST(EffectRejectOffscreen, RevealedBorderPixelsAreTheCurrentFrame) {
  const auto& on = renderOnce(kRejectionPan, "{}", {5}, currentAndVelocity());
  const auto& off =
      renderOnce(kRejectionPan, R"({"taa": {"reject_offscreen": false}})", {5}, currentAndVelocity());
  const test::Mask border = revealed(on[5]);
  report("revealed border pixels, frame 5", test::count(border));
  ASSERT_GT(test::count(border), 150);
  EXPECT_EQ(test::differing(on[5].color, test::capturedImage(on[5], Capture::Current), 0.0, border),
            0);
  const int differ =
      test::differing(off[5].color, test::capturedImage(off[5], Capture::Current), 1e-3, border);
  report("revealed pixels != current frame, reject_offscreen off", differ);
  EXPECT_GT(differ, test::count(border) / 2);
}

// Rough floor, static camera, a cube crossing at ~2 px per frame; no rectification.
const char* kRejectionMover = R"({
  "scene": {"builtin": "rough_floor"},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16},
  "movers": [{"shape": "cube", "start": [-3, 0.5, 2], "end": [3, 0.5, 2], "speed": 6, "repeat": "once"}],
  "taa": {"rectify": "none"}
})";

const std::vector<int> kRejectionFrames = {8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};

// Mean over frames 16-23 of the rmse against the reference where the mover was in the last 8
// frames but is no more.
double trailError(const std::string& patch) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Ids};
  const auto& truth = renderOnce(kRejectionMover, "{}", kRejectionFrames, o);
  const auto& run = renderOnce(kRejectionMover, patch, {16, 17, 18, 19, 20, 21, 22, 23});
  double sum = 0.0;
  for (int f = 16; f <= 23; ++f)
    sum += test::rmse(run[f].color, truth[f].reference, test::vacatedMask(truth, f - 8, f));
  report("mean rmse in the vacated trail, " + patch, sum / 8.0);
  return sum / 8.0;
}

TEST(EffectDepthCulling, ClearsTheTrailOfAMover) {
  EXPECT_LT(trailError(R"({"taa": {"depth_culling": true}})"), 0.6 * trailError("{}"));
}

TEST(EffectConsistency, ClearsTheTrailOfAMover) {
  EXPECT_LT(trailError(R"({"taa": {"consistency": true}})"), 0.6 * trailError("{}"));
}

TEST(EffectAntiGhosting, ClearsTheTrailOfAMover) {
  EXPECT_LT(trailError(R"({"taa": {"anti_ghosting": true}})"), 0.6 * trailError("{}"));
}

// Frame 1 is the first with history, and both runs' histories (frame 0's input) are equal, so
// any difference comes from this frame's blend.
TEST(EffectRejectionAlpha, ChangesRejectedPixelsOnly) {
  const char* culled = R"({"taa": {"depth_culling": true, "rejection_alpha": 1.0}})";
  const auto& one = renderOnce(kRejectionMover, culled, {1});
  const auto& half =
      renderOnce(kRejectionMover, R"({"taa": {"depth_culling": true, "rejection_alpha": 0.5}})", {1});
  const auto& mask = renderOnce(
      kRejectionMover, R"({"taa": {"depth_culling": true}, "debug": {"output": "rejection"}})", {1});
  const Image& rejected = mask[1].color;
  const test::Mask isRejected = test::maskWhere(
      rejected.width, rejected.height, [&](int x, int y) { return rejected.at(x, y, 0) > 0.5f; });
  report("rejected pixels, frame 1", test::count(isRejected));
  ASSERT_GT(test::count(isRejected), 20);
  EXPECT_EQ(test::differing(one[1].color, half[1].color, 0.0, test::maskNot(isRejected)), 0);
  const int changed = test::differing(one[1].color, half[1].color, 1e-3, isRejected);
  report("rejected pixels changed by rejection_alpha 0.5", changed);
  EXPECT_GT(changed, test::count(isRejected) / 2);
}

}  // namespace
}  // namespace taa
