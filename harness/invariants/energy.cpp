// energy: the resolve neither gains nor loses light. For every frame from checks.from_frame
// on, except history resets:
//   |mean L(output) - mean L(reference)| / max(mean L(reference), 1e-6) <= epsilon
// with L the Rec. 709 luminance of linear RGB, averaged over all pixels in double.
#include <algorithm>
#include <cmath>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

double meanLuminance(const Image& img) {
  double sum = 0.0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) sum += luminance(img, x, y);
  return img.pixelCount() ? sum / double(img.pixelCount()) : 0.0;
}

class Energy : public Invariant {
 public:
  explicit Energy(const CheckedCase& spec)
      : epsilon_(spec.checks.energy.epsilon), fromFrame_(spec.checks.from_frame) {}

  void observe(const FrameView& f) override {
    if (!error_.empty() || f.historyReset) return;
    error_ = requireCaptures(f, 3, {{Capture::Reference, 3}});
    if (!error_.empty()) return;
    const double out = meanLuminance(*f.output),
                 ref = meanLuminance(*f.capture(Capture::Reference));
    const double rel = std::fabs(out - ref) / std::max(ref, 1e-6);
    ++frames_;
    // NaN counts as the worst, so a non-finite mean is reported and fails.
    if (worstFrame_ < 0 || (!std::isnan(worst_) && (std::isnan(rel) || rel > worst_)))
      worst_ = rel, worstFrame_ = f.frame, worstOut_ = out, worstRef_ = ref;
    if (!(rel <= epsilon_)) ++framesOver_;
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (frames_ == 0) {
      o.detail = "no frame from checks.from_frame " + std::to_string(fromFrame_) +
                 " on outside a history reset";
      return o;
    }
    o.values = {{"worst_relative_difference", worst_},
                {"bound", epsilon_},
                {"frame", worstFrame_},
                {"output_mean_luminance", worstOut_},
                {"reference_mean_luminance", worstRef_},
                {"frames_over", double(framesOver_)},
                {"frames", double(frames_)}};
    o.passed = framesOver_ == 0;
    o.detail = "mean luminance off the reference by " + num(worst_) + (o.passed ? " <= " : " > ") +
               num(epsilon_) + " (relative) at worst, frame " + std::to_string(worstFrame_) + ": " +
               num(worstOut_) + " vs " + num(worstRef_) + "; " + std::to_string(framesOver_) +
               " of " + std::to_string(frames_) + " frame(s) over";
    return o;
  }

 private:
  double epsilon_;
  int fromFrame_;
  std::string error_;
  int frames_ = 0, framesOver_ = 0;
  double worst_ = 0.0, worstOut_ = 0.0, worstRef_ = 0.0;
  int worstFrame_ = -1;
};

std::string energyInapplicable(const CheckedCase& spec) {
  return debugViewReason("energy", spec);
}

std::unique_ptr<Invariant> makeEnergy(const CheckedCase& spec) {
  return std::make_unique<Energy>(spec);
}

}  // namespace

const InvariantInfo energy_invariant = {"energy",           {.captures = {Capture::Reference}},
                                        Frames::FromFrame,  "energy",
                                        energyInapplicable, makeEnergy};

}  // namespace taa::invariants
