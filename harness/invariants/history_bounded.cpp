// history_bounded: the resolve's output never leaves the box of the current frame's 3x3
// neighbourhood, i.e. rectification really bounds what history can contribute.
//
// Why this holds where it applies (shaders/taa_resolve.comp): the box is built from the taps
// after NaN rejection and clamping to [0, 65504]; shaped, variance and clip boxes lie inside
// that min/max box; the rectified history and the current sample lie in it, and with tonemap
// weighting none or karis the output is a convex blend of the two. What moves the output by
// more than rounding is modelled in history_box.h: shrink_chroma's wider chroma extent, and
// negative RGB (YCoCg box corners) lifted to zero by boundColor or Karis' max(history, 0).
//
// Tolerance per pixel: 2^-10 x its largest output channel + 2^-20 x the box's largest bound
// + 1e-6 (see checkPixel), plus for clip the 2^-10 x largest bound by which the resolve
// widens the box it clips against (shaders/taa/rectify.glsl). Frames that reset the history are skipped; every other frame is
// checked, warm-up included, because the bound holds from the first blended frame on.
#include <algorithm>
#include <cmath>
#include <limits>

#include "invariants/history_box.h"
#include "invariants/invariant_support.h"
#include "spec/taa_modes.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

constexpr double kInf = std::numeric_limits<double>::infinity();

class HistoryBounded : public Invariant {
 public:
  // A user's resolve that declares it clamps (taa.shader_clamps) promises the RGB min/max
  // box; the built-in settings do not describe it.
  explicit HistoryBounded(const CheckedCase& spec)
      : ycocg_(spec.taa.shader.empty() && spec.taa.color_space == ColorSpace::YCoCg),
        clip_(spec.taa.shader.empty() && spec.taa.rectify == Rectify::Clip),
        shrinkChroma_(ycocg_ && spec.taa.shrink_chroma),
        lift_(spec.taa.shader.empty() && spec.taa.tonemap_weighting == ToneWeight::Karis
                  ? box::Lift::NegativeChannels
                  : box::Lift::ZeroChannels) {}

  void observe(const FrameView& f) override {
    if (!error_.empty() || f.historyReset) return;
    error_ = requireCaptures(f, 3, {{Capture::Current, 3}});
    if (!error_.empty()) return;
    ++framesChecked_;
    for (int y = 0; y < f.output->height; ++y)
      for (int x = 0; x < f.output->width; ++x) checkPixel(f, x, y);
  }

  Outcome finish() override {
    Outcome o;
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    o.values = {{"max_excess", worstExcess_},
                {"tolerance", worstTol_},
                {"pixels_over", double(pixelsOver_)},
                {"frames_checked", double(framesChecked_)},
                {"frame", worstFrame_},
                {"x", worstX_},
                {"y", worstY_}};
    const std::string where = " at frame " + std::to_string(worstFrame_) + " (" +
                              std::to_string(worstX_) + ", " + std::to_string(worstY_) + ")";
    if (framesChecked_ == 0) {
      o.detail = "no frame with history to check";
      return o;
    }
    o.passed = pixelsOver_ == 0;
    o.detail = o.passed
                   ? "every output pixel inside its 3x3 box (largest excess " + num(worstExcess_) +
                         " <= tolerance " + num(worstTol_) + where + ")"
                   : std::to_string(pixelsOver_) + " pixel(s) outside the 3x3 box; worst excess " +
                         num(worstExcess_) + " > tolerance " + num(worstTol_) + where;
    return o;
  }

 private:
  void checkPixel(const FrameView& f, int x, int y) {
    const box::Box b =
        box::neighbourhoodBox(*f.capture(Capture::Current), x, y, ycocg_, shrinkChroma_);
    double o[3];
    double big = 0.0, boxBig = 0.0;
    bool finite = true;
    for (int k = 0; k < 3; ++k) {
      o[k] = f.output->at(x, y, k);
      finite = finite && std::isfinite(o[k]);
      big = std::max(big, std::fabs(o[k]));
      boxBig = std::max({boxBig, std::fabs(b.lo[k]), std::fabs(b.hi[k])});
    }
    // Half floats round to 2^-11 relative; each working component is a combination of RGB
    // with absolute weights summing to 1, so twice that step covers the stored output.
    // 2^-20 of the box covers the resolve's float32 arithmetic.
    const double tol = std::ldexp(big, -10) + std::ldexp(boxBig, clip_ ? -10 : -20) + 1e-6;
    double e = finite ? box::excess(o, b, ycocg_) : kInf;
    if (finite && e > tol && ycocg_) e = std::min(e, box::liftedExcess(o, b, lift_));
    if (e > tol) ++pixelsOver_;
    if (e - tol > worstMargin_) {
      worstMargin_ = e - tol;
      worstExcess_ = e, worstTol_ = tol;
      worstFrame_ = f.frame, worstX_ = x, worstY_ = y;
    }
  }

  bool ycocg_;
  bool clip_;
  bool shrinkChroma_;
  box::Lift lift_;
  std::string error_;
  int framesChecked_ = 0;
  long long pixelsOver_ = 0;
  double worstMargin_ = -kInf, worstExcess_ = 0.0, worstTol_ = 0.0;
  int worstFrame_ = -1, worstX_ = -1, worstY_ = -1;
};

std::string historyBoundedInapplicable(const CheckedCase& spec) {
  const std::string name = "history_bounded";
  const TaaSpec& t = spec.taa;
  auto because = [&](const std::string& why, const std::string& fix) {
    return name + " checks the clamp/clip box, but " + why +
           "; remove it from checks.invariants or " + fix;
  };
  if (!modeRule(t.mode).plainFull)
    return because(std::string("taa.mode is ") + enumToString(t.mode),
                   "set taa.mode to " + modeNames(modesWhere(&ModeRule::plainFull)));
  if (!t.shader.empty() && !t.shader_clamps)
    return because("the user's resolve (taa.shader) does not declare that it clamps",
                   "set taa.shader_clamps to true if its output stays in the 3x3 min/max box");
  if (t.shader.empty() && t.rectify == Rectify::None)
    return because("taa.rectify is none", "enable taa.rectify");
  if (t.shader.empty() && t.tonemap_weighting != ToneWeight::None && t.tonemap_weighting != ToneWeight::Karis)
    return because(std::string("taa.tonemap_weighting is ") + enumToString(t.tonemap_weighting) +
                       ", whose blend is not convex and may leave the box",
                   "set taa.tonemap_weighting to none or karis");
  if (spec.post.sharpen != Sharpen::None)
    return because(std::string("post.sharpen is ") + enumToString(spec.post.sharpen) +
                       ", which changes the output after the resolve",
                   "set post.sharpen to none");
  if (spec.post.fxaa)
    return because("post.fxaa changes the output after the resolve", "set post.fxaa to false");
  if (spec.render.upsample != 1.0f)
    return because("render.upsample is " + num(spec.render.upsample) +
                       " (the box is per render pixel, the output per output pixel)",
                   "set render.upsample to 1");
  if (!spec.render.scale_schedule.empty())
    return because("render.scale_schedule changes the render size", "remove render.scale_schedule");
  if (spec.debug.output != DebugOutput::None)
    return because(std::string("debug.output is ") + enumToString(spec.debug.output) +
                       ", which replaces the output",
                   "set debug.output to none");
  return "";
}

std::unique_ptr<Invariant> makeHistoryBounded(const CheckedCase& spec) {
  return std::make_unique<HistoryBounded>(spec);
}

}  // namespace

const InvariantInfo history_bounded_invariant = {
    "history_bounded", {.captures = {Capture::Current}}, Frames::FromFrame,
    nullptr,           historyBoundedInapplicable,       makeHistoryBounded};

}  // namespace taa::invariants
