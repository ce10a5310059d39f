// History reprojection: depth + inverse view-projection and the motion-vector buffer agree on
// static geometry; only velocity follows a mover; the depth-closest velocity of the 3x3
// neighbourhood keeps a mover's silhouette from taking the background's motion.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

const std::vector<int> kLast8 = {16, 17, 18, 19, 20, 21, 22, 23};

// Mean over frames 16-23 of the rmse against `truth`'s references over `mask(frame)`.
template <class MaskFn>
double meanError(const test::EffectRun& run, const test::EffectRun& truth, MaskFn mask) {
  double sum = 0.0;
  for (int f : kLast8) sum += test::rmse(run[f].color, truth[f].reference, mask(f));
  return sum / double(kLast8.size());
}

// Static scene, camera strafing and turning.
const char* kCamera = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"strafe": {"speed": 1.0}, "rotate": {"yaw_deg_per_s": 15}},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16}
})";

TEST(EffectReprojection, DepthMatchesVelocityOnAStaticSceneUnderCameraMotion) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Current};
  const auto& all = renderOnce(kCamera, R"({"taa": {"use_velocity": "all"}})", kLast8, o);
  const auto& off = renderOnce(kCamera, R"({"taa": {"use_velocity": "off"}})", kLast8);
  const auto whole = [](int) { return test::Mask{}; };
  const double eAll = meanError(all, all, whole), eOff = meanError(off, all, whole);
  double eRaw = 0.0;  // the jittered frames themselves: what no history would give
  for (int f : kLast8)
    eRaw +=
        test::rmse(test::capturedImage(all[f], Capture::Current), all[f].reference) / kLast8.size();
  report("mean rmse vs reference, use_velocity all (velocity)", eAll);
  report("mean rmse vs reference, use_velocity off (depth)", eOff);
  report("mean rmse vs reference, raw jittered frames", eRaw);
  EXPECT_LT(eAll, 0.75 * eRaw);
  EXPECT_LT(eOff, 0.75 * eRaw);
  EXPECT_NEAR(eOff, eAll, 0.05 * eAll);
}

// Static camera; a cube crossing the checkerboard at ~2 px per frame.
const char* kReprojectionMover = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16},
  "movers": [{"shape": "cube", "start": [-3, 0.5, 2], "end": [3, 0.5, 2], "speed": 6, "repeat": "once"}]
})";

RenderOptions withIds(bool reference) {
  RenderOptions o;
  if (reference) o.captures |= {Capture::Reference};
  o.captures |= {Capture::Ids};
  return o;
}

TEST(EffectReprojection, VelocityFollowsAMoverThatDepthReprojectionSmears) {
  const std::vector<int> frames = {8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
  const auto& all =
      renderOnce(kReprojectionMover, R"({"taa": {"use_velocity": "all"}})", frames, withIds(true));
  const auto& movers = renderOnce(kReprojectionMover, R"({"taa": {"use_velocity": "movers"}})", kLast8);
  const auto& off = renderOnce(kReprojectionMover, R"({"taa": {"use_velocity": "off"}})", kLast8);
  // The mover and 3 pixels around it: its own pixels and the strip it just left.
  const auto around = [&](int f) { return test::dilate(test::moverMask(all[f]), 160, 90, 3); };
  const double eAll = meanError(all, all, around), eMovers = meanError(movers, all, around),
               eOff = meanError(off, all, around);
  report("mean rmse around the mover, use_velocity all", eAll);
  report("mean rmse around the mover, use_velocity movers", eMovers);
  report("mean rmse around the mover, use_velocity off", eOff);
  EXPECT_GT(eOff, 1.3 * eAll);
  EXPECT_GT(eOff, 1.3 * eMovers);
  EXPECT_NEAR(eMovers, eAll, 0.05 * eAll);
  // Where the mover was 1-8 frames ago velocity changes nothing (the background is static
  // either way; clearing that trail is rejection's and rectification's job).
  const auto vacated = [&](int f) { return test::vacatedMask(all, f - 8, f); };
  report("mean rmse in the vacated trail, use_velocity all", meanError(all, all, vacated));
  report("mean rmse in the vacated trail, use_velocity off", meanError(off, all, vacated));
}

TEST(EffectVelocitySampling, Closest3x3ReducesErrorAtAMoverSilhouette) {
  const auto& closest =
      renderOnce(kReprojectionMover, R"({"taa": {"use_velocity": "all"}})",
                 {8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23}, withIds(true));
  const auto& pixel = renderOnce(
      kReprojectionMover, R"({"taa": {"use_velocity": "all", "velocity_sampling": "pixel"}})", kLast8);
  const auto edge = [&](int f) { return test::silhouetteMask(closest[f], 1); };
  const double eClosest = meanError(closest, closest, edge),
               ePixel = meanError(pixel, closest, edge);
  report("mean rmse at the silhouette (+-1 px), closest3x3", eClosest);
  report("mean rmse at the silhouette (+-1 px), pixel", ePixel);
  EXPECT_LT(eClosest, 0.92 * ePixel);
}

}  // namespace
}  // namespace taa
