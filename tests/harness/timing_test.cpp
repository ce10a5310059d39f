// The run's per-pass time summary: nearest-rank percentiles (the value at sorted index
// ceil(p/100 * N) - 1, the first value for p = 0) and the summary's rows, in the order
// the passes came, then "frame".
#include "run/timing.h"

#include <gtest/gtest.h>

namespace taa::timing_test {
namespace {

TEST(Percentile, NearestRankOnFewAndManyValues) {
  EXPECT_EQ(run::percentile({}, 50.0), 0.0);
  EXPECT_EQ(run::percentile({7.0}, 50.0), 7.0);
  EXPECT_EQ(run::percentile({7.0}, 95.0), 7.0);
  // Two values: the median's rank is 1, the lower one (not a mean of the two).
  EXPECT_EQ(run::percentile({9.0, 4.0}, 50.0), 4.0);
  EXPECT_EQ(run::percentile({9.0, 4.0}, 95.0), 9.0);
  EXPECT_EQ(run::percentile({9.0, 4.0, 6.0}, 0.0), 4.0);
  std::vector<double> twenty;
  for (int i = 20; i >= 1; --i) twenty.push_back(double(i));
  EXPECT_EQ(run::percentile(twenty, 50.0), 10.0);
  EXPECT_EQ(run::percentile(twenty, 95.0), 19.0);
  EXPECT_EQ(run::percentile(twenty, 100.0), 20.0);
}

TEST(TimingLog, RowsInTheOrderPassesCameThenTheFrameSum) {
  run::TimingLog log;
  log.add({{"gbuffer", 2.0}, {"resolve", 1.0}, {"reference", 50.0}});
  log.add({{"gbuffer", 4.0}, {"resolve", 3.0}, {"reference", 70.0}});
  const auto rows = log.summary();
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].pass, "gbuffer");
  EXPECT_EQ(rows[1].pass, "resolve");
  EXPECT_EQ(rows[2].pass, "reference");
  EXPECT_EQ(rows[3].pass, "frame");
  EXPECT_EQ(rows[0].medianMs, 2.0);
  EXPECT_EQ(rows[0].p95Ms, 4.0);
  // The frame leaves the reference out: 3 and 7 ms.
  EXPECT_EQ(rows[3].medianMs, 3.0);
  EXPECT_EQ(rows[3].p95Ms, 7.0);
}

}  // namespace
}  // namespace taa::timing_test
