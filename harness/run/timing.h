// Per-pass GPU times over a run, summarised as median and 95th percentile.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "run/results.h"

namespace taa::run {

// Milliseconds of one frame's own passes (the reference, a measuring aid, is left out).
double frameMilliseconds(const std::vector<std::pair<std::string, double>>& passes);

class TimingLog {
 public:
  void add(const std::vector<std::pair<std::string, double>>& passes);
  // One row per pass in first-seen order, then "frame" (the sum per frame).
  std::vector<PassTiming> summary() const;

 private:
  std::vector<std::string> order_;
  std::map<std::string, std::vector<double>> samples_;
};

// Nearest-rank percentile (p in [0, 100]) of `values`; 0 for none.
double percentile(std::vector<double> values, double p);

}  // namespace taa::run
