// tscmaa_non_edge on synthetic frames: CMAA may change only edge pixels, TAA only the
// TAA share of them.
#include <gtest/gtest.h>

#include "common/shared.h"
#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

struct TscmaaFrame {
  Image input = background(3), cmaa = background(3), output = background(3);
  Image mask = Image(kW, kH, 1, 0.0f);

  TscmaaFrame() {
    // (4, 4) is an edge pixel CMAA changed; (6, 4) one in the TAA share TAA changed.
    mask.at(4, 4) = float(TSCMAA_EDGE_LEFT);
    mask.at(6, 4) = float(TSCMAA_EDGE_TOP | TSCMAA_TAA);
    setRgb(cmaa, 4, 4, 0.5f, 0.5f, 0.5f);
    setRgb(output, 4, 4, 0.5f, 0.5f, 0.5f);
    setRgb(output, 6, 4, 0.9f, 0.1f, 0.1f);
  }

  FrameView view(int frame) const {
    FrameView v;
    v.frame = frame;
    v.output = &output;
    v.set(Capture::Current, &input);
    v.set(Capture::Cmaa, &cmaa);
    v.set(Capture::EdgeMask, &mask);
    return v;
  }
};

spec::CheckedCase tscmaaCase() {
  auto s = staticCase();
  s.taa.mode = spec::TaaMode::Tscmaa;
  return s;
}

Outcome runTscmaa(const std::vector<TscmaaFrame>& frames) {
  std::vector<FrameView> views;
  for (size_t i = 0; i < frames.size(); ++i) views.push_back(frames[i].view(int(i)));
  return runViews("tscmaa_non_edge", tscmaaCase(), views);
}

}  // namespace

TEST(TscmaaNonEdgeInvariant, ChangesWhereTheyAreAllowedPass) {
  const auto o = runTscmaa(std::vector<TscmaaFrame>(3));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "non_taa_pixels"), 3.0 * (kW * kH - 1));
  EXPECT_EQ(valueOf(o, "non_edge_pixels"), 3.0 * (kW * kH - 2));
}

TEST(TscmaaNonEdgeInvariant, TaaOutsideItsShareFails) {
  std::vector<TscmaaFrame> frames(2);
  setRgb(frames[1].output, 4, 4, 0.6f, 0.5f, 0.5f);  // an edge pixel, but not in the TAA share
  const auto o = runTscmaa(frames);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "non_taa_changed"), 1.0);
  EXPECT_NE(o.detail.find("frame 1 pixel 4,4"), std::string::npos) << o.detail;
}

TEST(TscmaaNonEdgeInvariant, CmaaOffTheEdgeListFails) {
  std::vector<TscmaaFrame> frames(1);
  setRgb(frames[0].cmaa, 9, 9, 0.0f, 0.0f, 0.0f);
  setRgb(frames[0].output, 9, 9, 0.0f, 0.0f, 0.0f);
  const auto o = runTscmaa(frames);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "non_edge_changed"), 1.0);
}

TEST(TscmaaNonEdgeInvariant, OnlyTscmaaCasesMayListIt) {
  EXPECT_NE(inapplicable("tscmaa_non_edge", staticCase()), "");
  EXPECT_EQ(inapplicable("tscmaa_non_edge", tscmaaCase()), "");
  auto fxaa = tscmaaCase();
  fxaa.post.fxaa = true;
  EXPECT_NE(inapplicable("tscmaa_non_edge", fxaa), "");
}
