// The lane runner every multi-lane command shares: lanes render frame by frame in lock-step,
// every lane of a frame sees lane 0's reference, a lane reads back only the frames it asks
// for, and the cost counts from `measureFrom` with one definition of TAA ms and frame ms.
#include "lanes/lane_runner.h"

#include <gtest/gtest.h>

#include <utility>
#include <vector>

#include "support/gpu.h"

namespace taa {
namespace {

TEST(LaneRunner, TaaMsLeavesOutTheRasterAndTheReferenceFrameMsOnlyTheReference) {
  const run::PassTimes passes = {{"gbuffer", 2.0},
                                 {"gbuffer_msaa", 1.0},
                                 {"taa_resolve", 0.5},
                                 {"reference", 8.0},
                                 {"post_fxaa", 0.25}};
  EXPECT_DOUBLE_EQ(run::taaMilliseconds(passes), 0.75);
  EXPECT_DOUBLE_EQ(run::frameMilliseconds(passes), 3.75);
  EXPECT_DOUBLE_EQ(run::mean({1.0, 2.0, 6.0}), 3.0);
  EXPECT_DOUBLE_EQ(run::mean({}), 0.0);
}

TEST(LaneRunner, LanesRunInLockStepAgainstLaneZerosReference) {
  const spec::CaseSpec a = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 32, "height": 18},
    "camera": {"strafe": {"speed": 1.5, "distance": 0.5}}, "script": {"frames": 4},
    "reference": {"samples": 2}})");
  spec::CaseSpec b = a;
  b.taa.alpha = 1.0f;  // another parameter set of the same replay
  lanes::LaneSetup first{&a, nullptr, {}, {}};
  first.options.captures = {Capture::Reference};
  lanes::LaneSetup second{&b, nullptr, {}, [](int f) { return f != 1; }};
  lanes::LaneRunner runner(test::device(), {first, second});
  ASSERT_EQ(runner.size(), 2u);
  EXPECT_FALSE(runner.log(1).empty());

  std::vector<std::pair<size_t, int>> order, before;
  std::vector<const Image*> references;
  runner.run(
      [&](lanes::LaneFrame& lf) {
        order.emplace_back(lf.lane, lf.record.frame);
        references.push_back(&lf.reference);
        if (lf.lane == 1) {
          EXPECT_FALSE(lf.record.hasReference);  // only lane 0 renders one
          EXPECT_EQ(lf.record.hasImages, lf.record.frame != 1) << lf.record.frame;
        }
        EXPECT_FALSE(lf.reference.data.empty())
            << "lane " << lf.lane << " frame " << lf.record.frame;
      },
      2, [&](size_t lane, int f) { before.emplace_back(lane, f); });

  const std::vector<std::pair<size_t, int>> lockStep = {{0, 0}, {1, 0}, {0, 1}, {1, 1},
                                                        {0, 2}, {1, 2}, {0, 3}, {1, 3}};
  EXPECT_EQ(order, lockStep);
  EXPECT_EQ(before, lockStep);
  for (size_t k = 0; k < references.size(); k += 2)
    EXPECT_EQ(references[k], references[k + 1])
        << "frame " << k / 2 << ": both lanes see lane 0's reference";
  for (size_t lane = 0; lane < 2; ++lane) {
    const auto& cost = runner.cost(lane);
    EXPECT_EQ(cost.taaMs.size(), 2u);  // frames 2 and 3
    EXPECT_EQ(cost.frameMs.size(), 2u);
    for (size_t k = 0; k < 2; ++k) EXPECT_LE(cost.taaMs[k], cost.frameMs[k]);
  }
}

}  // namespace
}  // namespace taa
