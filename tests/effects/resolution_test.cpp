// Resolution: temporal upsampling gathers jittered half-resolution frames into a full-resolution
// image better than any one of them upscaled; under dynamic resolution the velocity is scaled by
// each frame's actual render size, so panning error stays near the fixed-resolution run's.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

TEST(EffectUpsample, ConvergesTowardTheFullResolutionReference) {
  const char* half = R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 160, "height": 90, "upsample": 2},
    "jitter": {"pattern": "halton", "length": 16},
    "script": {"frames": 32},
    "reference": {"samples": 16},
    "taa": {"alpha": 0.2, "rectify": "none"}
  })";
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Current};
  const auto& run = renderOnce(half, "{}", {0, 31}, o);
  const Image& ref = run[31].reference;
  const double first = test::rmse(run[0].color, ref), last = test::rmse(run[31].color, ref);
  const Image& low = test::capturedImage(run[31], Capture::Current);
  const double upscaled = test::rmse(test::bilinearUpscale(low, 160, 90), ref);
  report("rmse vs full-res reference, frame 0", first);
  report("rmse vs full-res reference, frame 31", last);
  report("rmse vs full-res reference, bilinear upscale of frame 31's 80x45 input", upscaled);
  EXPECT_EQ(low.width, 80);
  EXPECT_LT(last, 0.75 * first);
  EXPECT_LT(last, 0.8 * upscaled);
}

const char* kResolutionPan = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"rotate": {"yaw_deg_per_s": 40}},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16}
})";

TEST(EffectDynamicResolution, PanningErrorStaysCloseToTheFixedResolutionRun) {
  const std::vector<int> frames = {12, 13, 14, 15, 20, 21, 22, 23};
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto& fixed = renderOnce(kResolutionPan, "{}", frames, o);
  const auto& dynamic = renderOnce(
      kResolutionPan,
      R"({"render": {"scale_schedule": [{"frame": 0, "scale": 1.0}, {"frame": 6, "scale": 0.7},
                                               {"frame": 16, "scale": 0.85}]}})",
      frames);
  double eFixed = 0.0, eDynamic = 0.0;
  for (int f : frames) {
    eFixed += test::rmse(fixed[f].color, fixed[f].reference) / frames.size();
    eDynamic += test::rmse(dynamic[f].color, fixed[f].reference) / frames.size();
  }
  report("render size at frame 12 (scale 0.7)", dynamic[12].renderSize.x);
  report("mean rmse under a pan, fixed resolution", eFixed);
  report("mean rmse under a pan, dynamic resolution", eDynamic);
  EXPECT_EQ(dynamic[12].renderSize.x, 112);
  EXPECT_LT(eDynamic, 1.5 * eFixed);
}

}  // namespace
}  // namespace taa
