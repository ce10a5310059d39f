// Issue 18 (seed fidelity): settings that were accepted and then ignored on some path now act
// there or are refused, and the resolve's deviations from the seeds are fixed: depth culling on
// the velocity path (and geometric consistency) expects the surface's depth of last frame,
// velocity sampling keeps the pixel itself on ties, and seed 001's velocity attenuation exists.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/case_problems.h"
#include "support/effects.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

std::vector<std::string> seedCaseProblems(const std::string& members) {
  return test::caseRefusal([&] {
    test::caseFromJson(R"({"scene": {"builtin": "checkerboard"}, )" + members + "}",
                       "seed_fidelity");
  });
}

bool seedMentions(const std::vector<std::string>& problems, const std::string& key,
                  const std::string& text) {
  for (const auto& p : problems)
    if (p.find(key) != std::string::npos && p.find(text) != std::string::npos) return true;
  return false;
}

TEST(SeedFidelityRefusals, ColorSpaceNeedsRectification) {
  EXPECT_TRUE(seedMentions(seedCaseProblems(R"("taa": {"rectify": "none", "color_space": "rgb"})"),
                           "taa.color_space", "taa.rectify is clamp or clip"));
  EXPECT_TRUE(seedCaseProblems(R"("taa": {"rectify": "clamp", "color_space": "rgb"})").empty());
}

TEST(SeedFidelityRefusals, DebugScaleOnlyWhereTheViewScales) {
  EXPECT_TRUE(seedMentions(seedCaseProblems(R"("debug": {"output": "rejection", "scale": 2})"),
                           "debug.scale", "velocity or clamp_distance"));
  EXPECT_TRUE(seedMentions(
      seedCaseProblems(
          R"("taa": {"mode": "adaptive"}, "debug": {"output": "segmentation", "scale": 2})"),
      "debug.scale", "velocity or clamp_distance"));
  EXPECT_TRUE(seedCaseProblems(R"("debug": {"output": "velocity", "scale": 2})").empty());
  EXPECT_TRUE(seedCaseProblems(R"("debug": {"output": "clamp_distance", "scale": 2})").empty());
}

TEST(SeedFidelityRefusals, TraceDisoccludedNeedsAnOnScreenRejection) {
  EXPECT_TRUE(seedMentions(
      seedCaseProblems(R"("taa": {"mode": "adaptive"}, "adaptive": {"trace_disoccluded": true})"),
      "adaptive.trace_disoccluded", "taa.depth_culling"));
  for (const char* test : {"depth_culling", "consistency"})
    EXPECT_TRUE(seedCaseProblems(std::string(R"("taa": {"mode": "adaptive", ")") + test +
                                 R"(": true}, "adaptive": {"trace_disoccluded": true})")
                    .empty())
        << test;
}

double seedStat(const FrameRecord& r, const std::string& name) {
  for (const auto& [k, v] : r.stats)
    if (k == name) return v;
  ADD_FAILURE() << "frame " << r.frame << " has no stat " << name;
  return -1.0;
}

// The cube uncovers floor every frame; depth culling rejects that floor on screen.
TEST(SeedFidelityTraceDisoccluded, TracesTheRejectedPixelsInsteadOfFxaa) {
  auto run = [](bool trace) {
    const auto spec = test::caseFromJson(
        std::string(R"({"scene": {"builtin": "rough_floor"}, "render": {"width": 160, "height": 90},
          "movers": [{"shape": "cube", "start": [-2.5, 0.5, 2], "end": [2.5, 0.5, 2], "speed": 4}],
          "taa": {"mode": "adaptive", "depth_culling": true},
          "adaptive": {"history_count": 0, "trace_disoccluded": )") +
        (trace ? "true" : "false") + R"(}, "script": {"frames": 5}})");
    return test::renderCase(spec, {}).back();
  };
  const FrameRecord off = run(false), on = run(true);
  test::report("traced share, trace_disoccluded off", seedStat(off, "traced_share"));
  test::report("traced share, trace_disoccluded on", seedStat(on, "traced_share"));
  test::report("fxaa share, trace_disoccluded off", seedStat(off, "fxaa_share"));
  test::report("fxaa share, trace_disoccluded on", seedStat(on, "fxaa_share"));
  // At least 20 pixels (of 14,400) move from FXAA to tracing.
  EXPECT_GT(seedStat(on, "traced_share"), seedStat(off, "traced_share") + 20.0 / 14400.0);
  EXPECT_LT(seedStat(on, "fxaa_share"), seedStat(off, "fxaa_share"));
}

int rejectedPixels(const std::string& json, int frame) {
  const auto& run = test::renderOnce(json, R"({"debug": {"output": "rejection"}})", {frame});
  const Image& mask = run[frame].color;
  return test::count(test::maskWhere(mask.width, mask.height,
                                     [&](int x, int y) { return mask.at(x, y, 0) > 0.5f; }));
}

// Dolly forward over static geometry at ~0.5 units a frame: the previous depth at the
// reprojected position is the surface's depth last frame, which the velocity path must expect,
// as the depth path does. Both reject the same ~2,000 pixels (disocclusions; the nearest-pixel
// depth lookup near the horizon); expecting this frame's depth instead rejected 11,740 of 14,400.
// Pixels rejected at frame 3 of a dolly over the open area with these `taa` members.
int rejectedUnderDolly(const std::string& taa) {
  return rejectedPixels(R"({"scene": {"builtin": "open_area"},
    "render": {"width": 160, "height": 90}, "jitter": {"pattern": "none"},
    "camera": {"path": {"type": "bezier", "points": [[0, 1.6, 6], [0, 1.6, -2]],
                        "duration_s": 0.25, "look": "fixed"}},
    "script": {"frames": 4}, "taa": {)" +
                            taa + "}}",
                        3);
}

// `taa` rejects about as few pixels under the dolly as depth culling on the depth path, which
// compares with the reprojected clip depth, last frame's depth by construction.
void expectDollyRejectsLikeTheDepthPath(const std::string& what, const std::string& taa) {
  const int tested = rejectedUnderDolly(taa);
  const int depthPath = rejectedUnderDolly(R"("depth_culling": true, "use_velocity": "off")");
  test::report("rejected pixels under a dolly, " + what, tested);
  test::report("rejected pixels under a dolly, depth culling on the depth path", depthPath);
  EXPECT_LT(tested, 160 * 90 / 4);
  EXPECT_LE(tested, depthPath + 160 * 90 / 100);
}

TEST(SeedFidelityDepthCulling, VelocityPathExpectsLastFramesDepth) {
  expectDollyRejectsLikeTheDepthPath("depth culling on the velocity path",
                                     R"("depth_culling": true, "use_velocity": "all")");
}

// Geometric consistency tests each tap against the depth the pixel's surface had last frame,
// as depth culling does: under the same dolly it keeps the history of the surfaces it keeps
// (comparing with this frame's depth, it rejected 12,750 of 14,400 pixels; now about 125, the
// disocclusions beside the trunks).
TEST(SeedFidelityConsistency, DollyKeepsTheSurfacesHistory) {
  expectDollyRejectsLikeTheDepthPath("consistency", R"("consistency": true)");
}

// Sky against sky is consistent: it has no normal (the G-buffer holds zero there) and no depth
// to compare, so testing them rejected every sky pixel of every frame.
TEST(SeedFidelityConsistency, StillViewRejectsNothingSkyIncluded) {
  const std::string still = R"({"scene": {"builtin": "open_area"},
    "render": {"width": 160, "height": 90}, "jitter": {"pattern": "none"},
    "script": {"frames": 3}, "taa": {"consistency": true}})";
  EXPECT_EQ(rejectedPixels(still, 2), 0);
}

// A still view: every velocity is zero, so longest3x3 ties everywhere. The pixel itself must
// win, or the reprojection takes the (-1,-1) neighbour's depth and depth culling rejects the
// pixels along every silhouette although nothing moved.
TEST(SeedFidelityVelocitySampling, StillViewTakesThePixelItself) {
  const std::string still = R"({"scene": {"builtin": "open_area"},
    "render": {"width": 160, "height": 90}, "jitter": {"pattern": "none"},
    "script": {"frames": 3}, "taa": {"depth_culling": true, "velocity_sampling": "longest3x3"}})";
  EXPECT_EQ(rejectedPixels(still, 2), 0);
}

// Seed 001: one pixel away halves the history's weight. Uniform history 0 and current 1, so
// the output is alpha itself: 1 - (1 - 0.1) / (1 + d) with the attenuation, 0.1 without.
TEST(SeedFidelityVelocityAttenuation, HistoryWeightIsDividedByOnePlusTheDistance) {
  auto resolve = [](bool attenuate, float velocityPx) {
    const std::string json = std::string(R"({
      "scene": {"builtin": "checkerboard"}, "render": {"width": 16, "height": 8},
      "jitter": {"pattern": "none"}, "script": {"frames": 2},
      "taa": {"use_velocity": "all", "velocity_sampling": "pixel", "history_filter": "bilinear",
              "reject_offscreen": false, "rectify": "none", "alpha": 0.1,
              "history_format": "rgba32f", "velocity_attenuation": )") +
                             (attenuate ? "true" : "false") + "}}";
    test::SyntheticResolve in;
    in.current = Image(16, 8, 4, 1.0f);
    in.history = Image(16, 8, 4, 0.0f);
    in.velocityPx = {velocityPx, 0.0f};
    return test::gpuResolve(test::caseFromJson(json, "velocity_attenuation"), in)
        .output.at(8, 4, 0);
  };
  EXPECT_NEAR(resolve(false, 1.0f), 0.1f, 1e-5f);
  EXPECT_NEAR(resolve(true, 0.0f), 0.1f, 1e-5f);
  EXPECT_NEAR(resolve(true, 1.0f), 1.0f - 0.9f / 2.0f, 1e-5f);
  EXPECT_NEAR(resolve(true, 3.0f), 1.0f - 0.9f / 4.0f, 1e-5f);
}

// On a scene: a cube crossing the checkerboard at ~1 px per frame with no rectification. The
// depth-closest 3x3 velocity gives the pixels it just left its speed, so their history weight
// drops and the trail it leaves is shorter than at a fixed alpha.
TEST(SeedFidelityVelocityAttenuation, ShortensTheTrailOfAMover) {
  const char* mover =
      R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 160, "height": 90},
    "script": {"frames": 24}, "reference": {"samples": 16},
    "movers": [{"shape": "cube", "start": [-3, 0.5, 2], "end": [3, 0.5, 2], "speed": 3, "repeat": "once"}],
    "taa": {"rectify": "none"}})";
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Ids};
  const std::vector<int> frames = {8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
  const auto& plain = test::renderOnce(mover, "{}", frames, o);
  const auto& on = test::renderOnce(mover, R"({"taa": {"velocity_attenuation": true}})",
                                    {16, 17, 18, 19, 20, 21, 22, 23});
  double ePlain = 0.0, eOn = 0.0;
  for (int f = 16; f <= 23; ++f) {
    const test::Mask vacated = test::vacatedMask(plain, f - 8, f);
    ePlain += test::rmse(plain[f].color, plain[f].reference, vacated) / 8.0;
    eOn += test::rmse(on[f].color, plain[f].reference, vacated) / 8.0;
  }
  test::report("trail rmse, fixed alpha", ePlain);
  test::report("trail rmse, velocity_attenuation", eOn);
  EXPECT_LT(eOn, 0.9 * ePlain);
}

}  // namespace
}  // namespace taa
