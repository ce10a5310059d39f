// no_ghosting: once a mover has left a pixel, history rejection must let the pixel return to
// the background within K frames. At frame f the checked pixels are those covered by a
// mover at frame f-K and by none in f-K+1..f; their mean |tonemapped luma(output) -
// tonemapped luma(reference)| must stay within max_error. Each vacated pixel is judged
// exactly K frames after the mover left, when a ghost trail of length K would still show.
// Memory: the last frame each pixel was covered, not a window of masks.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

class NoGhosting : public Invariant {
 public:
  explicit NoGhosting(const CheckedCase& spec)
      : k_(spec.checks.no_ghosting.frames), maxError_(spec.checks.no_ghosting.max_error) {}

  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    error_ = requireCaptures(f, 3, {{Capture::Reference, 3}, {Capture::Ids, 3}});
    if (!error_.empty()) return;
    const Image& ids = *f.capture(Capture::Ids);
    if (lastCovered_.empty()) lastCovered_.assign(ids.pixelCount(), kNever);
    if (lastCovered_.size() != ids.pixelCount()) {
      error_ = "frame " + std::to_string(f.frame) + ": the image size changed";
      return;
    }
    // Coverage first: a pixel covered now is not vacated, whatever it was before.
    for (int y = 0; y < ids.height; ++y)
      for (int x = 0; x < ids.width; ++x)
        if (ids.at(x, y, 2) != 0.0f)
          lastCovered_[size_t(y) * size_t(ids.width) + size_t(x)] = f.frame;

    double sum = 0.0;
    long long count = 0;
    for (int y = 0; y < ids.height; ++y)
      for (int x = 0; x < ids.width; ++x) {
        if (lastCovered_[size_t(y) * size_t(ids.width) + size_t(x)] != f.frame - k_) continue;
        sum += std::fabs(double(tonemappedLuma(*f.output, x, y)) -
                         double(tonemappedLuma(*f.capture(Capture::Reference), x, y)));
        ++count;
      }
    if (count == 0) return;
    ++framesWithPixels_;
    const double mean = sum / double(count);
    // NaN compares false both ways: treat it as the worst so it is reported and fails.
    const bool worse =
        worstFrame_ < 0 || (!std::isnan(worst_) && (std::isnan(mean) || mean > worst_));
    if (worse) worst_ = mean, worstFrame_ = f.frame, worstCount_ = count;
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (framesWithPixels_ == 0) {
      o.detail =
          "no vacated pixels: the case does not exercise this (no pixel was left by a mover " +
          std::to_string(k_) + " frames before a checked frame)";
      return o;
    }
    o.values = {{"worst_mean_error", worst_},
                {"bound", maxError_},
                {"frame", worstFrame_},
                {"pixels", double(worstCount_)},
                {"frames_checked", double(framesWithPixels_)}};
    o.passed = worst_ <= maxError_;
    o.detail = "pixels vacated " + std::to_string(k_) +
               " frames earlier: worst mean tonemapped-luma error " + num(worst_) +
               (o.passed ? " <= " : " > ") + num(maxError_) + " at frame " +
               std::to_string(worstFrame_) + " over " + std::to_string(worstCount_) + " pixel(s)";
    return o;
  }

 private:
  static constexpr int kNever = std::numeric_limits<int>::min() / 2;
  int k_;
  double maxError_;
  std::string error_;
  std::vector<int> lastCovered_;
  int framesWithPixels_ = 0;
  double worst_ = 0.0;
  int worstFrame_ = -1;
  long long worstCount_ = 0;
};

bool moverMoves(const MoverSpec& m) {
  return m.speed > 0.0f || m.rotation_speed_deg != 0.0f ||
         (m.shape == MoverShape::Gltf && m.animation_speed > 0.0f);
}

std::string noGhostingInapplicable(const CheckedCase& spec) {
  const std::string name = "no_ghosting";
  if (spec.movers.empty())
    return name +
           " checks pixels movers leave behind, but the case has no movers; remove it from "
           "checks.invariants or add a moving entry to movers";
  if (std::none_of(spec.movers.begin(), spec.movers.end(), moverMoves))
    return name +
           " checks pixels movers leave behind, but no mover moves (speed 0, no rotation); remove "
           "it from checks.invariants or give a mover a speed";
  if (auto r = noHistoryReason(name, spec); !r.empty()) return r;
  if (auto r = renderSizeReason(name, spec); !r.empty()) return r;
  return debugViewReason(name, spec);
}

std::unique_ptr<Invariant> makeNoGhosting(const CheckedCase& spec) {
  return std::make_unique<NoGhosting>(spec);
}

}  // namespace

const InvariantInfo no_ghosting_invariant = {
    "no_ghosting",          {.captures = {Capture::Reference, Capture::Ids}},
    Frames::FromFrame,      "no_ghosting",
    noGhostingInapplicable, makeNoGhosting};

}  // namespace taa::invariants
