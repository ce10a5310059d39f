// temporal_stability: static pixels must not flicker much more than the reference does.
//   static at f: |velocity| < 0.01 px and no mover (ids channel 2 == 0), at f and at f-1 (a
//                pixel a mover just left changes for a reason that is not flicker)
//   flicker_f  = mean over static pixels of |tl(x_f) - tl(x_{f-1})|, tl = tonemapped luma
//   flicker    = mean of flicker_f over frames from checks.from_frame on that have static
//                pixels, skipping history resets (a reset or cut is a legitimate jump)
// The same pixels and frames give the reference's flicker; the check passes when
//   flicker_output <= factor * flicker_reference + epsilon.
// Memory: the previous frame's tonemapped lumas and static mask.
#include <cmath>
#include <vector>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

constexpr float kStaticPx = 0.01f;

class TemporalStability : public Invariant {
 public:
  explicit TemporalStability(const CheckedCase& spec)
      : factor_(spec.checks.temporal_stability.factor),
        epsilon_(spec.checks.temporal_stability.epsilon) {}

  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    error_ =
        requireCaptures(f, 3, {{Capture::Reference, 3}, {Capture::Ids, 3}, {Capture::Velocity, 2}});
    if (!error_.empty()) return;
    const Image &reference = *f.capture(Capture::Reference), &ids = *f.capture(Capture::Ids),
                &velocity = *f.capture(Capture::Velocity);
    const int w = f.output->width, h = f.output->height;
    const size_t n = f.output->pixelCount();
    std::vector<float> out(n), ref(n);
    std::vector<char> still(n);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = size_t(y) * size_t(w) + size_t(x);
        out[i] = tonemappedLuma(*f.output, x, y);
        ref[i] = tonemappedLuma(reference, x, y);
        const float vx = velocity.at(x, y, 0), vy = velocity.at(x, y, 1);
        still[i] = std::sqrt(vx * vx + vy * vy) < kStaticPx && ids.at(x, y, 2) == 0.0f;
      }
    const bool comparable = havePrev_ && prevOut_.size() == n && prevFrame_ == f.frame - 1;
    if (comparable && !f.historyReset) {
      ++framesSeen_;
      double dOut = 0.0, dRef = 0.0;
      long long count = 0;
      for (size_t i = 0; i < n; ++i) {
        if (!still[i] || !prevStill_[i]) continue;
        dOut += std::fabs(double(out[i]) - double(prevOut_[i]));
        dRef += std::fabs(double(ref[i]) - double(prevRef_[i]));
        ++count;
      }
      if (count > 0) {
        sumOut_ += dOut / double(count);
        sumRef_ += dRef / double(count);
        staticPixels_ += count;
        ++frames_;
      }
    }
    prevOut_ = std::move(out);
    prevRef_ = std::move(ref);
    prevStill_ = std::move(still);
    prevFrame_ = f.frame;
    havePrev_ = true;
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (frames_ == 0) {
      o.detail = "no static pixels (velocity < 0.01 px, no mover, in two consecutive frames) in " +
                 std::to_string(framesSeen_) +
                 " frame pair(s) checked; the camera or movers cover everything";
      return o;
    }
    const double flicker = sumOut_ / frames_, reference = sumRef_ / frames_;
    const double bound = factor_ * reference + epsilon_;
    o.values = {{"flicker", flicker},
                {"reference_flicker", reference},
                {"bound", bound},
                {"frames", double(frames_)},
                {"mean_static_pixels", double(staticPixels_) / frames_}};
    o.passed = flicker <= bound;
    o.detail = "static-pixel flicker " + num(flicker) + (o.passed ? " <= " : " > ") + num(factor_) +
               " x reference " + num(reference) + " + " + num(epsilon_) + " = " + num(bound) +
               " over " + std::to_string(frames_) + " frame(s)";
    return o;
  }

 private:
  double factor_, epsilon_;
  std::string error_;
  std::vector<float> prevOut_, prevRef_;
  std::vector<char> prevStill_;
  int prevFrame_ = -1;
  bool havePrev_ = false;
  int framesSeen_ = 0, frames_ = 0;
  long long staticPixels_ = 0;
  double sumOut_ = 0.0, sumRef_ = 0.0;
};

std::string temporalStabilityInapplicable(const CheckedCase& spec) {
  const std::string name = "temporal_stability";
  if (auto r = noHistoryReason(name, spec); !r.empty()) return r;
  if (auto r = renderSizeReason(name, spec); !r.empty()) return r;
  return debugViewReason(name, spec);
}

std::unique_ptr<Invariant> makeTemporalStability(const CheckedCase& spec) {
  return std::make_unique<TemporalStability>(spec);
}

}  // namespace

const InvariantInfo temporal_stability_invariant = {
    "temporal_stability",
    {.captures = {Capture::Reference, Capture::Ids, Capture::Velocity}},
    Frames::FromFrame,
    "temporal_stability",
    temporalStabilityInapplicable,
    makeTemporalStability};

}  // namespace taa::invariants
