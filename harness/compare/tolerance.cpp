#include "compare/tolerance.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "compare/flip.h"
#include "compare/metrics.h"
#include "core/image_io.h"

namespace taa::compare {

Image displayedPng(const Image& hdr) {
  Image d = toDisplaySrgb(hdr);  // no NaN left: NaN pixels are magenta
  // The same rounding as writePng's 8-bit quantization (core/image_io.cpp), expression for
  // expression.
  for (float& v : d.data) {
    const float clamped = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    v = float(std::lround(clamped * 255.0f)) / 255.0f;
  }
  return d;
}

Measured measureAgainstGolden(const Image& golden, const Image& actual, float pixelThreshold) {
  MetricOptions options;
  options.threshold = pixelThreshold;
  const Metrics lin = computeMetrics(golden, actual, options);
  const FlipResult flip = flipLdr(displayedPng(golden), displayedPng(actual));
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
