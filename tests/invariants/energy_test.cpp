#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

// The output is the reference scaled by gain(f): mean luminance off by gain - 1.
template <class Gain>
std::vector<Frame> sequenceEnergy(int frames, Gain gain) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.reference = background();
    fr.output = fr.reference;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < 3; ++c) fr.output.at(x, y, c) *= gain(f);
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantEnergy, SmallDifferencePasses) {
  const auto o = runAll("energy", staticCase(), sequenceEnergy(6, [](int) { return 1.01f; }));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_NEAR(valueOf(o, "worst_relative_difference"), 0.01, 1e-5);
}

TEST(InvariantEnergy, BrightenedOutputFailsAtItsFrame) {
  const auto o =
      runAll("energy", staticCase(), sequenceEnergy(6, [](int f) { return f == 4 ? 1.1f : 1.0f; }));
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "frame"), 4.0);
  EXPECT_EQ(valueOf(o, "frames_over"), 1.0);
  EXPECT_NEAR(valueOf(o, "worst_relative_difference"), 0.1, 1e-5);
  EXPECT_TRUE(contains(o.detail, "> 0.02")) << o.detail;
}

TEST(InvariantEnergy, DarkenedOutputFails) {
  EXPECT_FALSE(runAll("energy", staticCase(), sequenceEnergy(4, [](int) { return 0.9f; })).passed);
}

TEST(InvariantEnergy, ResetsAndWarmUpAreSkipped) {
  auto s = staticCase();
  s.checks.from_frame = 2;
  auto seq = sequenceEnergy(6, [](int f) { return f < 2 || f == 4 ? 1.5f : 1.0f; });
  seq[4].reset = true;
  const auto o = runAll("energy", s, seq);
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "frames"), 3.0);
}

TEST(InvariantEnergy, InapplicableOnlyToDebugViews) {
  auto s = staticCase();
  s.taa.mode = spec::TaaMode::Off;
  s.render.upsample = 2.0f;
  EXPECT_EQ(inapplicable("energy", s), "");
  s.debug.output = spec::DebugOutput::Velocity;
  EXPECT_TRUE(contains(inapplicable("energy", s),
                       "energy measures the image, but debug.output is velocity"));
}
