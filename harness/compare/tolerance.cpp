#include "compare/tolerance.h"

#include <cstdio>
#include <stdexcept>

#include "compare/flip.h"
#include "compare/metrics.h"

namespace taa::compare {

Measured measureAgainstGolden(const Image& golden, const Image& actual, float pixelThreshold) {
  MetricOptions options;
  options.threshold = pixelThreshold;
  const Metrics lin = computeMetrics(golden, actual, options);
  const FlipResult flip = flipLdrFromHdr(golden, actual);
  Measured out;
  out.metrics.maxAbs = lin.maxAbsError;
  out.metrics.rmse = lin.rmse;
  out.metrics.psnr = lin.psnr;
  out.metrics.shareOver = lin.shareOverThreshold;
  out.metrics.flipMean = flip.mean;
  out.metrics.flipP99 = flip.p99;
  out.errorMap = flip.errorMap;
  return out;
}

namespace {
std::string line(const char* name, double value, const char* op, double bound) {
  char buf[128];
  std::snprintf(buf, sizeof(buf), "%s %.6g %s %.6g", name, value, op, double(bound));
  return buf;
}
}  // namespace

std::vector<std::string> toleranceViolations(const run::ImageMetrics& m, const spec::ToleranceSpec& t) {
  // Written as !(value <= bound) so that NaN metrics count as violations.
  std::vector<std::string> out;
  if (!(m.maxAbs <= t.max_abs)) out.push_back(line("max_abs", m.maxAbs, ">", t.max_abs));
  if (!(m.rmse <= t.rmse)) out.push_back(line("rmse", m.rmse, ">", t.rmse));
  if (!(m.psnr >= t.psnr_min)) out.push_back(line("psnr", m.psnr, "<", t.psnr_min));
  if (!(m.shareOver <= t.pixels_over)) out.push_back(line("share_over", m.shareOver, ">", t.pixels_over));
  if (!(m.flipMean <= t.flip_mean)) out.push_back(line("flip_mean", m.flipMean, ">", t.flip_mean));
  if (!(m.flipP99 <= t.flip_p99)) out.push_back(line("flip_p99", m.flipP99, ">", t.flip_p99));
  return out;
}

double metricByName(const run::ImageMetrics& m, const std::string& name) {
  if (name == "max_abs") return m.maxAbs;
  if (name == "rmse") return m.rmse;
  if (name == "psnr") return m.psnr;
  if (name == "share_over") return m.shareOver;
  if (name == "flip_mean") return m.flipMean;
  if (name == "flip_p99") return m.flipP99;
  throw std::invalid_argument("unknown metric '" + name +
                              "'; use one of max_abs, rmse, psnr, share_over, flip_mean, flip_p99");
}

}  // namespace taa::compare
