// adaptive_unmarked on synthetic frames: passes when only marked pixels differ from
// the resolve's output, fails on one changed unmarked pixel (even by one ulp), and
// applies only to adaptive cases whose output is the adaptive pass's.
#include <gtest/gtest.h>

#include <cmath>

#include "common/shared.h"
#include "invariants/invariant_fixtures.h"

namespace taa::invariants {
namespace {

using namespace fixtures;

struct AdaptiveFrame {
  Image output = background(), resolved = background(), mask = Image(kW, kH, 1, 0.0f);
  FrameView view(int frame) const {
    FrameView v;
    v.frame = frame;
    v.output = &output;
    v.set(Capture::Resolved, &resolved);
    v.set(Capture::Segmentation, &mask);
    return v;
  }
};

spec::CheckedCase adaptiveCase() {
  spec::CheckedCase s = staticCase();
  s.taa.mode = spec::TaaMode::Adaptive;
  return s;
}

Outcome runAdaptive(const std::vector<AdaptiveFrame>& frames) {
  std::vector<FrameView> views;
  for (size_t i = 0; i < frames.size(); ++i) views.push_back(frames[i].view(int(i)));
  return runViews("adaptive_unmarked", adaptiveCase(), views);
}

TEST(AdaptiveUnmarkedInvariant, PassesWhenOnlyMarkedPixelsChange) {
  std::vector<AdaptiveFrame> frames(3);
  for (auto& f : frames) {
    f.mask.at(3, 4) = float(ADAPTIVE_MASK_TRACE);
    f.mask.at(5, 4) = float(ADAPTIVE_MASK_TRACE_HISTORY);
    f.mask.at(0, 0) = float(ADAPTIVE_MASK_FXAA);
    setRgb(f.output, 3, 4, 0.0f, 0.0f, 0.0f);
    setRgb(f.output, 5, 4, 9.0f, 9.0f, 9.0f);
    setRgb(f.output, 0, 0, 0.5f, 0.5f, 0.5f);
  }
  const auto o = runAdaptive(frames);
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_NEAR(valueOf(o, "traced_share"), 2.0 / (kW * kH), 1e-9);
  EXPECT_NEAR(valueOf(o, "fxaa_share"), 1.0 / (kW * kH), 1e-9);
}

TEST(AdaptiveUnmarkedInvariant, FailsOnOneUnmarkedPixelChangedByOneUlp) {
  for (int c = 0; c < 3; ++c) {  // in any one channel
    std::vector<AdaptiveFrame> frames(2);
    float& v = frames[1].output.at(7, 2, c);
    v = std::nextafter(v, 2.0f);
    const auto o = runAdaptive(frames);
    EXPECT_FALSE(o.passed) << "channel " << c;
    EXPECT_TRUE(contains(o.detail, "frame 1 pixel (7, 2)")) << o.detail;
    EXPECT_EQ(valueOf(o, "differing_unmarked_pixels"), 1.0);
  }
}

TEST(AdaptiveUnmarkedInvariant, FailsWithoutTheCapturedImages) {
  AdaptiveFrame f;
  FrameView v = f.view(0);
  v.set(Capture::Segmentation, nullptr);
  const auto o = runViews("adaptive_unmarked", adaptiveCase(), {v});
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "segmentation")) << o.detail;
}

TEST(AdaptiveUnmarkedInvariant, AppliesToAdaptiveCasesOnly) {
  EXPECT_TRUE(needsOf("adaptive_unmarked").captures.has(Capture::Segmentation));
  EXPECT_EQ(inapplicable("adaptive_unmarked", adaptiveCase()), "");
  EXPECT_TRUE(contains(inapplicable("adaptive_unmarked", staticCase()), "taa.mode"));
  auto sharpened = adaptiveCase();
  sharpened.post.sharpen = spec::Sharpen::Cas;
  EXPECT_TRUE(contains(inapplicable("adaptive_unmarked", sharpened), "post.sharpen"));
  auto debug = adaptiveCase();
  debug.debug.output = spec::DebugOutput::Segmentation;
  EXPECT_NE(inapplicable("adaptive_unmarked", debug), "");
}

}  // namespace
}  // namespace taa::invariants
