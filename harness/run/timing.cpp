#include "run/timing.h"

#include <algorithm>
#include <cmath>

namespace taa::run {

namespace {

bool isRasterPass(const std::string& pass) { return pass.rfind("gbuffer", 0) == 0; }

}  // namespace

double frameMilliseconds(const PassTimes& passes) {
  double sum = 0.0;
  for (const auto& [name, ms] : passes)
    if (name != "reference") sum += ms;
  return sum;
}

double taaMilliseconds(const PassTimes& passes) {
  double sum = 0.0;
  for (const auto& [name, ms] : passes)
    if (name != "reference" && !isRasterPass(name)) sum += ms;
  return sum;
}

void TimingLog::add(const PassTimes& passes) {
  for (const auto& [name, ms] : passes) {
    if (!samples_.count(name)) order_.push_back(name);
    samples_[name].push_back(ms);
  }
  if (!samples_.count("frame")) order_.push_back("frame");
  samples_["frame"].push_back(frameMilliseconds(passes));
}

std::vector<PassTiming> TimingLog::summary() const {
  std::vector<PassTiming> out;
  std::vector<std::string> names = order_;
  // "frame" last, whatever order the passes came in.
  names.erase(std::remove(names.begin(), names.end(), "frame"), names.end());
  if (samples_.count("frame")) names.push_back("frame");
  for (const auto& n : names) out.push_back({n, percentile(samples_.at(n), 50.0), percentile(samples_.at(n), 95.0)});
  return out;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<size_t>(std::ceil(p / 100.0 * double(values.size())));
  return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

double mean(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? 0.0 : sum / double(values.size());
}

}  // namespace taa::run
