#include "compare/metric_table.h"

#include <cstdio>

namespace taa::compare {

namespace {

constexpr auto kMetricLinear = MetricSource::Linear;
constexpr auto kMetricFlip = MetricSource::Flip;

const MetricInfo kMetricRows[] = {
    {"max_abs", "max abs", Better::Lower, kMetricLinear,
     [](const Metrics& m, const FlipResult&) { return m.maxAbsError; }, &run::ImageMetrics::maxAbs,
     &spec::ToleranceSpec::max_abs, false},
    {"mean_abs", "mean abs", Better::Lower, kMetricLinear,
     [](const Metrics& m, const FlipResult&) { return m.meanAbsError; }, nullptr, nullptr, false},
    {"rmse", "RMSE", Better::Lower, kMetricLinear,
     [](const Metrics& m, const FlipResult&) { return m.rmse; }, &run::ImageMetrics::rmse,
     &spec::ToleranceSpec::rmse, true},
    {"psnr", "PSNR dB", Better::Higher, kMetricLinear,
     [](const Metrics& m, const FlipResult&) { return m.psnr; }, &run::ImageMetrics::psnr,
     &spec::ToleranceSpec::psnr_min, false},
    {"share_over", "share over", Better::Lower, kMetricLinear,
     [](const Metrics& m, const FlipResult&) { return m.shareOverThreshold; },
     &run::ImageMetrics::shareOver, &spec::ToleranceSpec::pixels_over, false},
    {"flip_mean", "FLIP mean", Better::Lower, kMetricFlip,
     [](const Metrics&, const FlipResult& f) { return f.mean; }, &run::ImageMetrics::flipMean,
     &spec::ToleranceSpec::flip_mean, true},
    {"flip_p50", "FLIP p50", Better::Lower, kMetricFlip,
     [](const Metrics&, const FlipResult& f) { return double(f.p50); }, nullptr, nullptr, false},
    {"flip_p95", "FLIP p95", Better::Lower, kMetricFlip,
     [](const Metrics&, const FlipResult& f) { return double(f.p95); }, nullptr, nullptr, false},
    {"flip_p99", "FLIP p99", Better::Lower, kMetricFlip,
     [](const Metrics&, const FlipResult& f) { return double(f.p99); }, &run::ImageMetrics::flipP99,
     &spec::ToleranceSpec::flip_p99, false},
    {"flip_max", "FLIP max", Better::Lower, kMetricFlip,
     [](const Metrics&, const FlipResult& f) { return double(f.max); }, nullptr, nullptr, false},
};

}  // namespace

std::span<const MetricInfo> metricTable() {
  return kMetricRows;
}

std::vector<const MetricInfo*> goldenMetrics() {
  std::vector<const MetricInfo*> out;
  for (const auto& row : kMetricRows)
    if (row.golden) out.push_back(&row);
  return out;
}

const MetricInfo* findMetric(std::string_view name) {
  for (const auto& row : kMetricRows)
    if (name == row.name) return &row;
  return nullptr;
}

std::string metricList(const std::vector<const MetricInfo*>& rows) {
  std::string out;
  for (const auto* row : rows) out += std::string(out.empty() ? "" : ", ") + row->name;
  return out;
}

bool violates(const MetricInfo& metric, double value, double bound) {
  // Written as !(value within bound) so that NaN violates.
  return metric.better == Better::Lower ? !(value <= bound) : !(value >= bound);
}

std::string violationLine(const MetricInfo& metric, double value, double bound) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%s %.6g %s %.6g", metric.name, value,
                metric.better == Better::Lower ? ">" : "<", bound);
  return buf;
}

bool isViolationOf(const MetricInfo& metric, std::string_view line) {
  const std::string_view name = metric.name;
  return line.starts_with(name) && line.size() > name.size() && line[name.size()] == ' ';
}

}  // namespace taa::compare
