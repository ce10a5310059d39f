#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

constexpr int kNoGhostingFrames = 12;
constexpr int kK = 3;

// A 3x3 red block moving right 1 px per frame over a textured background, from x = 1.
int moverLeft(int frame) {
  return 1 + frame;
}
bool covered(int x, int y, int frame) {
  return x >= moverLeft(frame) && x < moverLeft(frame) + 3 && y >= 4 && y < 7;
}

// The output shows the mover colour at pixels it left fewer than `trail` frames ago (a
// ghost), plus small deterministic noise everywhere.
std::vector<Frame> moverSequence(int trail, bool moving = true) {
  const Image bg = background();
  std::vector<Frame> seq;
  for (int f = 0; f < kNoGhostingFrames; ++f) {
    const int t = moving ? f : 0;
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.reference = bg;
    fr.ids = rgba(0, 0, 0);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        if (covered(x, y, t))
          setRgb(fr.reference, x, y, 0.9f, 0.1f, 0.1f), fr.ids.at(x, y, 2) = 1.0f;
    fr.output = fr.reference;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        bool ghost = false;
        for (int back = 1; back < trail && t - back >= 0; ++back)
          ghost = ghost || covered(x, y, t - back);
        if (ghost && !covered(x, y, t)) setRgb(fr.output, x, y, 0.9f, 0.1f, 0.1f);
        for (int c = 0; c < 3; ++c) fr.output.at(x, y, c) += 0.01f * (noise(x, y, f) - 0.5f);
      }
    seq.push_back(std::move(fr));
  }
  return seq;
}

spec::CheckedCase ghostCase() {
  auto s = moverCase();
  s.checks.no_ghosting.frames = kK;
  s.checks.no_ghosting.max_error = 0.05f;
  return s;
}

}  // namespace

TEST(InvariantNoGhosting, CleanTrailPasses) {
  const auto o = runAll("no_ghosting", ghostCase(), moverSequence(0));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_LT(valueOf(o, "worst_mean_error"), 0.01);
  EXPECT_EQ(valueOf(o, "pixels"), 3.0);  // one column of the block left kK frames ago
}

// A ghost that fades before K frames is allowed: only pixels vacated K frames ago count.
TEST(InvariantNoGhosting, GhostShorterThanKPasses) {
  const auto o = runAll("no_ghosting", ghostCase(), moverSequence(kK));
  EXPECT_TRUE(o.passed) << o.detail;
}

TEST(InvariantNoGhosting, GhostTrailBehindTheMoverFails) {
  const auto o = runAll("no_ghosting", ghostCase(), moverSequence(kK + 2));
  EXPECT_FALSE(o.passed);
  EXPECT_GT(valueOf(o, "worst_mean_error"), 0.05);
  EXPECT_TRUE(contains(o.detail, "> 0.05")) << o.detail;
}

TEST(InvariantNoGhosting, FromFrameSkipsEarlierFrames) {
  auto seq = moverSequence(0);
  setRgb(seq[kK + 1].output, moverLeft(1), 5, 5.0f, 5.0f, 5.0f);  // last covered at frame 1
  auto s = ghostCase();
  EXPECT_FALSE(runAll("no_ghosting", s, seq).passed);
  s.checks.from_frame = kK + 2;
  EXPECT_TRUE(runAll("no_ghosting", s, seq).passed);
}

TEST(InvariantNoGhosting, NoVacatedPixelsFails) {
  const auto o = runAll("no_ghosting", ghostCase(), moverSequence(0, false));
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "no vacated pixels: the case does not exercise this")) << o.detail;
}

TEST(InvariantNoGhosting, MissingIdsFails) {
  auto seq = moverSequence(0);
  seq[3].ids = Image();
  const auto o = runAll("no_ghosting", ghostCase(), seq);
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "frame 3: no material_id image")) << o.detail;
}

TEST(InvariantNoGhosting, InapplicableWithoutMovingMoversOrHistory) {
  EXPECT_EQ(inapplicable("no_ghosting", moverCase()), "");
  EXPECT_TRUE(contains(inapplicable("no_ghosting", staticCase()), "the case has no movers"));
  auto still = moverCase();
  still.movers[0].speed = 0.0f;
  EXPECT_TRUE(contains(inapplicable("no_ghosting", still), "no mover moves"));
  still.movers[0].rotation_speed_deg = 45.0f;  // a spinning cube uncovers pixels too
  EXPECT_EQ(inapplicable("no_ghosting", still), "");
  auto off = moverCase();
  off.taa.mode = spec::TaaMode::Off;
  EXPECT_TRUE(contains(inapplicable("no_ghosting", off), "taa.mode is off"));
  auto up = moverCase();
  up.render.upsample = 1.5f;
  EXPECT_TRUE(contains(inapplicable("no_ghosting", up), "render.upsample is 1.5"));
  auto dbg = moverCase();
  dbg.debug.output = spec::DebugOutput::Rejection;
  EXPECT_TRUE(contains(inapplicable("no_ghosting", dbg), "debug.output is rejection"));
}
