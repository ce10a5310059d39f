// The metric table: one row per name, and every consumer (tolerance check, results.json,
// `run --metric`) reading the same rows in the same order.
#include "compare/metric_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>

#include "compare/tolerance.h"

namespace taa::compare {
namespace {

TEST(MetricTable, NamesAreUniqueAndFound) {
  std::set<std::string> names;
  for (const auto& row : metricTable()) {
    EXPECT_TRUE(names.insert(row.name).second) << row.name << " twice";
    EXPECT_EQ(findMetric(row.name), &row);
  }
  EXPECT_EQ(findMetric("no_such_metric"), nullptr);
  EXPECT_EQ(metricList(goldenMetrics()), "max_abs, rmse, psnr, share_over, flip_mean, flip_p99");
}

TEST(MetricTable, GoldenRowsHaveAFieldAndABoundAndReadTheirOwnField) {
  run::ImageMetrics m;
  double v = 1.0;
  for (const auto* row : goldenMetrics()) {
    ASSERT_NE(row->bound, nullptr) << row->name;
    m.*row->golden = v;
    EXPECT_EQ(metricByName(m, row->name), v) << row->name;
    v += 1.0;
  }
  EXPECT_THROW(metricByName(m, "flip_p50"), std::invalid_argument);  // compare-only
}

TEST(MetricTable, ViolationFollowsTheDirectionAndNaNAlwaysViolates) {
  const MetricInfo& rmse = *findMetric("rmse");
  const MetricInfo& psnr = *findMetric("psnr");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(violates(rmse, 0.01, 0.02));
  EXPECT_TRUE(violates(rmse, 0.03, 0.02));
  EXPECT_FALSE(violates(psnr, 40.0, 30.0));
  EXPECT_TRUE(violates(psnr, 20.0, 30.0));
  EXPECT_TRUE(violates(rmse, nan, 0.02));
  EXPECT_TRUE(violates(psnr, nan, 30.0));
  EXPECT_EQ(violationLine(rmse, 0.03, 0.02), "rmse 0.03 > 0.02");
  EXPECT_EQ(violationLine(psnr, 20.0, 30.0), "psnr 20 < 30");
}

TEST(MetricTable, ToleranceViolationsListEveryBoundInTableOrder) {
  run::ImageMetrics m;
  m.maxAbs = 2.0;     // > 1
  m.rmse = 0.5;       // > 0.02
  m.psnr = 10.0;      // < 30
  m.shareOver = 0.5;  // > 0.02
  m.flipMean = 0.5;   // > 0.01
  m.flipP99 = 0.5;    // > 0.1
  const auto lines = toleranceViolations(m, spec::ToleranceSpec{});
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0], "max_abs 2 > 1");
  EXPECT_EQ(lines[2], "psnr 10 < 30");
  EXPECT_EQ(lines[3], "share_over 0.5 > 0.02");
  EXPECT_EQ(lines[5], "flip_p99 0.5 > 0.1");
  EXPECT_TRUE(toleranceViolations(run::ImageMetrics{0.0, 0.0, 99.0, 0.0, 0.0, 0.0}, {}).empty());
}

// The report marks a failed cell by matching the frame's failure lines to its column: a line
// belongs to its own metric only, even where one name starts another's.
TEST(MetricTable, AViolationLineIsRecognisedAsItsOwnMetricOnly) {
  for (const auto& row : metricTable())
    for (const auto& other : metricTable())
      EXPECT_EQ(&row == &other, isViolationOf(other, violationLine(row, 2.0, 1.0)))
          << row.name << " vs " << other.name;
  const MetricInfo* rmse = findMetric("rmse");
  ASSERT_NE(rmse, nullptr);
  EXPECT_FALSE(isViolationOf(*rmse, "rmse"));
  // A line that is the name alone is none, wherever its text sits: here a view that ends where
  // a longer line goes on with a space (reading past the view's end would see that space).
  const std::string longer = "rmse 2 > 1";
  EXPECT_FALSE(isViolationOf(*rmse, std::string_view(longer).substr(0, 4)));
  EXPECT_FALSE(isViolationOf(*rmse, "rmsex 2 > 1"));
  EXPECT_FALSE(isViolationOf(*rmse, "size 64x36 differs"));
}

}  // namespace
}  // namespace taa::compare
