#include <cmath>

#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

std::vector<Frame> sequenceMatchesInput(int frames) {
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.output = background();
    fr.current = background();
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantMatchesInput, IdenticalOutputPasses) {
  const auto o = runAll("matches_input", staticCase(), sequenceMatchesInput(3));
  EXPECT_TRUE(o.passed) << o.detail;
}

TEST(InvariantMatchesInput, OneUlpOffFailsWithTheLocation) {
  auto seq = sequenceMatchesInput(3);
  float& v = seq[2].output.at(4, 5, 1);
  v = std::nextafter(v, 10.0f);
  const auto o = runAll("matches_input", staticCase(), seq);
  EXPECT_FALSE(o.passed);
  EXPECT_NE(o.detail.find("frame 2 (4, 5) channel 1"), std::string::npos) << o.detail;
}

// Bit for bit, not ==: a NaN passed through is the input, and -0 for +0 is not.
TEST(InvariantMatchesInput, ComparesBitsNotValues) {
  auto seq = sequenceMatchesInput(2);
  for (auto& f : seq) {
    f.current.at(1, 1, 0) = f.output.at(1, 1, 0) = std::nanf("");
    f.current.at(2, 2, 2) = f.output.at(2, 2, 2) = -0.0f;
  }
  const auto same = runAll("matches_input", staticCase(), seq);
  EXPECT_TRUE(same.passed) << same.detail;
  seq[1].output.at(2, 2, 2) = 0.0f;
  const auto zero = runAll("matches_input", staticCase(), seq);
  EXPECT_FALSE(zero.passed);
  EXPECT_NE(zero.detail.find("frame 1 (2, 2) channel 2"), std::string::npos) << zero.detail;
}

TEST(InvariantMatchesInput, PostPassesMakeItInapplicable) {
  auto spec = staticCase();
  spec.post.fxaa = true;
  EXPECT_NE(inapplicable("matches_input", spec).find("post"), std::string::npos);
}
