#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

// Hashes change every frame until `settle`, then stay, except at `blip`.
std::vector<Frame> hashesBitStable(int frames, int settle, int blip = -1) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.sha256 = "h" + std::to_string(f < settle ? f : settle);
    if (f == blip) fr.sha256 = "blip";
    seq.push_back(std::move(fr));
  }
  return seq;
}

spec::CheckedCase stableCase(int after) {
  auto s = staticCase();
  s.jitter.pattern = spec::JitterPattern::None;
  s.checks.bit_stable.after_frame = after;
  return s;
}

}  // namespace

TEST(InvariantBitStable, SettledOutputPasses) {
  const auto o = runAll("bit_stable", stableCase(5), hashesBitStable(16, 5));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "frames_compared"), 10.0);
}

TEST(InvariantBitStable, ChangeAfterTheFrameFails) {
  const auto o = runAll("bit_stable", stableCase(5), hashesBitStable(16, 5, 9));
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "first_change_frame"), 9.0);
  EXPECT_EQ(valueOf(o, "changes"), 2.0);  // into the blip and out of it
  EXPECT_TRUE(contains(o.detail, "first at frame 9")) << o.detail;
}

TEST(InvariantBitStable, AfterFrameZeroComparesFrameOneWithFrameZero) {
  const auto o = runAll("bit_stable", stableCase(0), hashesBitStable(8, 1));
  EXPECT_FALSE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "frames_compared"), 7.0);
  EXPECT_EQ(valueOf(o, "first_change_frame"), 1.0);
}

TEST(InvariantBitStable, StillSettlingAtAfterFrameFails) {
  EXPECT_FALSE(runAll("bit_stable", stableCase(5), hashesBitStable(16, 7)).passed);
}

TEST(InvariantBitStable, InapplicableWhenTheInputChanges) {
  EXPECT_EQ(inapplicable("bit_stable", stableCase(5)), "");
  EXPECT_TRUE(contains(
      inapplicable("bit_stable", stableCase(15)),
      "bit_stable compares frames after bit_stable.after_frame 15, but the last frame is 15"));
  auto moving = stableCase(5);
  moving.movers.emplace_back();
  EXPECT_TRUE(contains(inapplicable("bit_stable", moving),
                       "needs a static scene, but movers[0].speed is 1"));
  auto jittered = stableCase(5);
  jittered.jitter.pattern = spec::JitterPattern::Halton;
  EXPECT_TRUE(
      contains(inapplicable("bit_stable", jittered), "jitter.pattern halton moves the samples"));
  jittered.jitter.lock = 3;  // locked to one step: constant again
  EXPECT_EQ(inapplicable("bit_stable", jittered), "");
  auto reset = stableCase(5);
  reset.script.reset_history_at = {9};
  EXPECT_TRUE(contains(inapplicable("bit_stable", reset), "resets it at frame 9"));
  reset.script.reset_history_at = {3};
  EXPECT_EQ(inapplicable("bit_stable", reset), "");
}
