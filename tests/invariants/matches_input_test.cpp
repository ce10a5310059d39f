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

TEST(InvariantMatchesInput, PostPassesMakeItInapplicable) {
  auto spec = staticCase();
  spec.post.fxaa = true;
  EXPECT_NE(inapplicable("matches_input", spec).find("post"), std::string::npos);
}
