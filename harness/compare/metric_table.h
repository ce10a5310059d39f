// Every image metric the harness reports, in one table: its name (results.json key, tolerance
// violation line, `run --metric`, `compare --metric`), its report column, which way is better,
// how it is computed, where a golden comparison stores it and which tolerance bounds it.
// Adding a metric is adding a row here (and, when golden comparisons record it, a field of
// run::ImageMetrics and a bound in spec::ToleranceSpec).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "compare/flip.h"
#include "compare/metrics.h"
#include "run/results.h"
#include "spec/checks_spec.h"

namespace taa::compare {

enum class Better { Lower, Higher };
enum class MetricSource { Linear, Flip };  // computeMetrics (metrics.h) or FLIP (flip.h)

struct MetricInfo {
  const char* name;
  const char* title;  // report column header
  Better better;
  MetricSource source;
  double (*value)(const Metrics& linear, const FlipResult& flip);
  // Its field in a golden comparison's figures, or nullptr when only `compare` reports it.
  double run::ImageMetrics::*golden;
  // The tolerance bounding it when the environment differs from the goldens', or nullptr.
  float spec::ToleranceSpec::*bound;
  // Shown on the one line `run` prints for a frame that differs from its golden (the other
  // golden figures are in results.json and the report).
  bool summary;
};

// Every row, in output order.
std::span<const MetricInfo> metricTable();
// The rows with a golden field, in output order.
std::vector<const MetricInfo*> goldenMetrics();
const MetricInfo* findMetric(std::string_view name);
// "max_abs, rmse, ..." over `rows`.
std::string metricList(const std::vector<const MetricInfo*>& rows);

// Whether `value` is on the wrong side of `bound`: above it for Lower-is-better metrics, below
// it for Higher. NaN is always on the wrong side.
bool violates(const MetricInfo& metric, double value, double bound);
// "rmse 0.021 > 0.01"; the operator says which side was violated.
std::string violationLine(const MetricInfo& metric, double value, double bound);
// Whether `line` is a violationLine of `metric`.
bool isViolationOf(const MetricInfo& metric, std::string_view line);

}  // namespace taa::compare
