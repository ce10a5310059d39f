#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

std::vector<Frame> hashesDeterminism(int frames, int changedFrame = -1) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.sha256 = std::string(64, char('a' + f % 6));
    if (f == changedFrame) fr.sha256[63] = '0';
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantDeterminism, NeedsASecondRun) {
  EXPECT_TRUE(needsOf("determinism").secondRun);
}

TEST(InvariantDeterminism, IdenticalRepeatPasses) {
  const auto o = runAll("determinism", staticCase(), hashesDeterminism(8), hashesDeterminism(8));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "mismatches"), 0.0);
}

TEST(InvariantDeterminism, DifferentHashFailsNamingTheFrame) {
  const auto o = runAll("determinism", staticCase(), hashesDeterminism(8), hashesDeterminism(8, 5));
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "first_mismatch_frame"), 5.0);
  EXPECT_TRUE(contains(o.detail, "first: frame 5: ")) << o.detail;
}

TEST(InvariantDeterminism, SeveralDifferencesNameTheEarliest) {
  auto repeat = hashesDeterminism(8, 3);
  repeat[6].sha256[63] = '0';  // a second, later difference must not replace the first
  const auto o = runAll("determinism", staticCase(), hashesDeterminism(8), repeat);
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "mismatches"), 2.0);
  EXPECT_EQ(valueOf(o, "first_mismatch_frame"), 3.0);
  EXPECT_TRUE(contains(o.detail, "first: frame 3: ")) << o.detail;
}

TEST(InvariantDeterminism, ShortRepeatFails) {
  const auto o = runAll("determinism", staticCase(), hashesDeterminism(8), hashesDeterminism(6));
  EXPECT_FALSE(o.passed);
  EXPECT_EQ(valueOf(o, "first_mismatch_frame"), 6.0);
  EXPECT_TRUE(contains(o.detail, "the repeat has no frame 6")) << o.detail;
}

TEST(InvariantDeterminism, NoRepeatFails) {
  const auto o = runAll("determinism", staticCase(), hashesDeterminism(4));
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "not rendered a second time")) << o.detail;
}
