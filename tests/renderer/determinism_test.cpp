// Determinism is the product: the same case gives the same bytes in one process,
// across processes, and whatever number of threads lavapipe rasterises with.
#include <gtest/gtest.h>

#include <regex>

#include "support/gpu.h"
#include "support/process.h"

namespace taa {
namespace {

const char* kDeterminismMoving = R"({
  "scene": {"builtin": "rough_floor"},
  "camera": {"strafe": {"speed": 1.5, "distance": 0.5}, "rotate": {"yaw_deg_per_s": 10}},
  "movers": [{"shape": "sphere", "start": [-1.5, 0.5, 1], "end": [1.5, 0.5, 1], "speed": 2}],
  "script": {"frames": 8},
  "output": {"frames": [3, 7]}
})";

std::vector<std::string> hashes(const std::vector<FrameRecord>& frames) {
  std::vector<std::string> out;
  for (const auto& f : frames)
    if (f.hasImages) out.push_back(f.colorSha256);
  return out;
}

TEST(Determinism, TwoRendersInOneProcessAreIdentical) {
  const auto spec = test::caseFromJson(kDeterminismMoving, "determinism");
  const auto a = hashes(test::renderCase(spec));
  const auto b = hashes(test::renderCase(spec));
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a[0], a[1]);  // the frames differ, so equal hashes mean something
}

std::vector<std::string> renderedHashes(const std::string& env) {
  const std::string out = std::string(TAA_TEST_OUT) + "/determinism-" + env.substr(env.find('=') + 1);
  const auto r = test::runHarness(std::string("render ") + TAA_SOURCE_DIR + "/cases/checkerboard_static.json --out " + out, env);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  std::vector<std::string> found;
  const std::regex line("frame \\d+ sha256 ([0-9a-f]{64})");
  for (std::sregex_iterator it(r.output.begin(), r.output.end(), line), end; it != end; ++it)
    found.push_back((*it)[1]);
  return found;
}

TEST(Determinism, OneAndTwoLavapipeThreadsGiveIdenticalFrames) {
  const auto one = renderedHashes("LP_NUM_THREADS=1");
  const auto two = renderedHashes("LP_NUM_THREADS=2");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace taa
