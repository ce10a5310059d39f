#include <cmath>
#include <limits>

#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

std::vector<Frame> sequenceFinite(int frames) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.output = background();
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantFinite, FiniteFramesPass) {
  const auto o = runAll("finite", staticCase(), sequenceFinite(4));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "nonfinite_pixels"), 0.0);
}

TEST(InvariantFinite, NanAndInfFailWithCountAndFirstLocation) {
  auto seq = sequenceFinite(5);
  seq[2].output.at(3, 2, 1) = std::numeric_limits<float>::quiet_NaN();
  seq[2].output.at(9, 7, 0) = std::numeric_limits<float>::infinity();
  seq[4].output.at(0, 0, 3) = -std::numeric_limits<float>::infinity();  // alpha counts too
  const auto o = runAll("finite", staticCase(), seq);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "nonfinite_pixels"), 3.0);
  EXPECT_EQ(valueOf(o, "frames_with_nonfinite"), 2.0);
  EXPECT_EQ(valueOf(o, "frame"), 2.0);
  EXPECT_EQ(valueOf(o, "x"), 3.0);
  EXPECT_EQ(valueOf(o, "y"), 2.0);
  EXPECT_TRUE(contains(o.detail, "first at frame 2 (3, 2)")) << o.detail;
}

// Warm-up frames are checked too: a NaN is a defect whenever it appears.
TEST(InvariantFinite, IgnoresFromFrame) {
  auto seq = sequenceFinite(3);
  seq[0].output.at(1, 1, 0) = std::nanf("");
  auto s = staticCase();
  s.checks.from_frame = 2;
  EXPECT_FALSE(runAll("finite", s, seq).passed);
}

// An invariant that judged no frame has shown nothing: that is no pass.
TEST(InvariantFinite, NoFrameIsNoPass) {
  const auto o = runAll("finite", staticCase(), {});
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "no frames observed")) << o.detail;
}

TEST(InvariantFinite, ApplicableToEveryCase) {
  auto s = staticCase();
  s.taa.mode = spec::TaaMode::Off;
  s.debug.output = spec::DebugOutput::Velocity;
  EXPECT_EQ(inapplicable("finite", s), "");
}
