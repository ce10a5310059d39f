// adaptive_unmarked: adaptive ray tracing changes only the pixels its segmentation
// marks. Every frame, each pixel the mask leaves unmarked (mask::kAdaptiveNone) must
// equal the full resolve's output for that frame bit for bit: neither the trace nor
// the masked FXAA may touch it. Traced and FXAA'd pixels are counted for the report.

#include "invariants/invariant_support.h"
#include "spec/taa_modes.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

class AdaptiveUnmarked : public Invariant {
 public:
  void observe(const FrameView& f) override {
    if (!error_.empty()) return;
    error_ = requireCaptures(f, 3, {{Capture::Resolved, 3}, {Capture::Segmentation, 1}});
    if (!error_.empty()) return;
    const Image &resolved = *f.capture(Capture::Resolved),
                &segmentation = *f.capture(Capture::Segmentation);
    ++frames_;
    for (int y = 0; y < f.output->height; ++y)
      for (int x = 0; x < f.output->width; ++x) {
        const auto mark = uint32_t(segmentation.at(x, y, 0));
        ++pixels_;
        if (mark != mask::kAdaptiveNone) {
          ++(mark == mask::kAdaptiveFxaa ? fxaa_ : traced_);
          continue;
        }
        if (!sameRgbBits(*f.output, resolved, x, y) && differing_++ == 0)
          where_ = "frame " + std::to_string(f.frame) + " pixel (" + std::to_string(x) + ", " +
                   std::to_string(y) + ")";
      }
  }

  Outcome finish() override {
    Outcome o;
    const double n = pixels_ > 0 ? double(pixels_) : 1.0;
    o.values = {{"frames", double(frames_)},
                {"differing_unmarked_pixels", double(differing_)},
                {"traced_share", double(traced_) / n},
                {"fxaa_share", double(fxaa_) / n}};
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    if (frames_ == 0) {
      o.detail = "no frame observed";
      return o;
    }
    o.passed = differing_ == 0;
    o.detail = o.passed
                   ? "unmarked pixels equal the resolve's output in " + std::to_string(frames_) +
                         " frame(s) (traced " + num(double(traced_) / n) + ", FXAA " +
                         num(double(fxaa_) / n) + " of pixels)"
                   : std::to_string(differing_) +
                         " unmarked pixel(s) differ from the resolve's output; first at " + where_;
    return o;
  }

 private:
  std::string error_, where_;
  int frames_ = 0;
  long long pixels_ = 0, traced_ = 0, fxaa_ = 0, differing_ = 0;
};

std::string adaptiveUnmarkedInapplicable(const CheckedCase& spec) {
  const std::string name = "adaptive_unmarked";
  if (!modeRule(spec.taa.mode).adaptive)
    return name + " checks adaptive ray tracing, but taa.mode is " + enumToString(spec.taa.mode) +
           "; set taa.mode to " + modeNames(modesWhere(&ModeRule::adaptive)) +
           " or remove it from checks.invariants";
  if (auto why = debugViewReason(name, spec); !why.empty()) return why;
  if (spec.post.sharpen != Sharpen::None || spec.post.fxaa)
    return name +
           " compares the output with the resolve's, but post.sharpen / post.fxaa change every "
           "pixel "
           "after it; remove them or the invariant";
  return "";
}

std::unique_ptr<Invariant> makeAdaptiveUnmarked(const CheckedCase&) {
  return std::make_unique<AdaptiveUnmarked>();
}

}  // namespace

const InvariantInfo adaptive_unmarked_invariant = {
    "adaptive_unmarked",
    {.captures = {Capture::Resolved, Capture::Segmentation}},
    Frames::FromFrame,
    nullptr,
    adaptiveUnmarkedInapplicable,
    makeAdaptiveUnmarked};

}  // namespace taa::invariants
