// converges: in a static scene the accumulated history approaches the supersampled reference.
// Over the frames from checks.from_frame on (restarting at each history reset, since a reset
// restarts accumulation), with e_f = RMSE(output_f, reference_f) over linear RGB:
//   e_last <= ratio * e_first, and mean(e over the last quarter) <= mean(e over the first).
// Only one RMSE per frame is kept.
#include <cmath>
#include <vector>

#include "compare/metrics.h"
#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

class Converges : public Invariant {
 public:
  explicit Converges(const CheckedCase& spec) : ratio_(spec.checks.converges.ratio) {}

  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    error_ = requireCaptures(f, 3, {{Capture::Reference, 3}});
    if (!error_.empty()) return;
    if (f.historyReset || rmse_.empty()) {
      rmse_.clear();
      start_ = f.frame;
    }
    rmse_.push_back(compare::computeMetrics(*f.output, *f.capture(Capture::Reference)).rmse);
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    const size_t n = rmse_.size();
    if (n < 4) {
      o.detail = std::to_string(n) + " frame(s) from frame " + std::to_string(start_) +
                 " (checks.from_frame or the last history reset) on; converges needs at least 4";
      return o;
    }
    const size_t q = n / 4;
    double firstQ = 0.0, lastQ = 0.0;
    for (size_t i = 0; i < q; ++i) firstQ += rmse_[i], lastQ += rmse_[n - 1 - i];
    firstQ /= double(q);
    lastQ /= double(q);
    const double first = rmse_.front(), last = rmse_.back(), bound = ratio_ * first;
    o.values = {
        {"first_rmse", first},          {"last_rmse", last},          {"bound", bound},
        {"first_quarter_mean", firstQ}, {"last_quarter_mean", lastQ}, {"frames", double(n)}};
    const bool endOk = last <= bound, trendOk = lastQ <= firstQ;
    o.passed = endOk && trendOk;
    const std::string span =
        "frames " + std::to_string(start_) + ".." + std::to_string(start_ + int(n) - 1);
    o.detail = "RMSE to reference over " + span + ": last " + num(last) + (endOk ? " <= " : " > ") +
               num(ratio_) + " x first " + num(first) + " = " + num(bound) +
               "; last-quarter mean " + num(lastQ) + (trendOk ? " <= " : " > ") +
               "first-quarter mean " + num(firstQ);
    return o;
  }

 private:
  double ratio_;
  std::string error_;
  std::vector<double> rmse_;  // of the current accumulation run
  int start_ = 0;
};

std::string convergesInapplicable(const CheckedCase& spec) {
  const std::string name = "converges";
  if (auto what = whatMoves(spec); !what.empty())
    return name + " needs a static scene, but " + what +
           "; remove it from checks.invariants or stop the motion";
  if (auto r = noHistoryReason(name, spec); !r.empty()) return r;
  // Without sub-pixel jitter every frame samples the same points: nothing to accumulate.
  if (auto why = jitterConstant(spec); !why.empty())
    return name + " needs sub-pixel jitter to accumulate, but " + why +
           ", so every frame samples the same points; remove it from checks.invariants or enable "
           "jitter";
  return debugViewReason(name, spec);
}

std::unique_ptr<Invariant> makeConverges(const CheckedCase& spec) {
  return std::make_unique<Converges>(spec);
}

}  // namespace

const InvariantInfo converges_invariant = {
    "converges",           {.captures = {Capture::Reference}},
    Frames::FromFrame,     "converges",
    convergesInapplicable, makeConverges};

}  // namespace taa::invariants
