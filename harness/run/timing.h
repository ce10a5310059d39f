// Per-pass GPU times over a run, summarised as median and 95th percentile, and the one
// definition of a frame's cost that the run, sweep, score and report A/B all print.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "run/results.h"

namespace taa::run {

using PassTimes = std::vector<std::pair<std::string, double>>;

// "frame ms": milliseconds of one frame's own passes (the reference, a measuring aid, is left
// out).
double frameMilliseconds(const PassTimes& passes);
// "TAA ms": frame ms less the raster ("gbuffer..." passes): what the anti-aliasing adds, so an
// MSAA preset, all of whose work is in the raster, costs 0.
double taaMilliseconds(const PassTimes& passes);

class TimingLog {
 public:
  void add(const PassTimes& passes);
  // One row per pass in first-seen order, then "frame" (the sum per frame).
  std::vector<PassTiming> summary() const;

 private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> samples_;
};

// Nearest-rank percentile (p in [0, 100]) of `values`; 0 for none.
double percentile(std::vector<double> values, double p);
// The arithmetic mean, summed in order; 0 for none.
double mean(const std::vector<double>& values);

}  // namespace taa::run
