// history_bounded: the resolve's output never leaves the box of the current frame's 3x3
// neighbourhood, i.e. rectification really bounds what history can contribute.
//
// Why this holds for the cases it applies to (see shaders/taa_resolve.comp): the box is
// built from the taps after NaN rejection and clamping to [0, 65504]; shaped, variance and
// clip boxes all lie inside that min/max box; the rectified history lies in the box, the
// current sample lies in it, and with tonemap weighting none or karis the output is a convex
// blend of the two. Two things move the output by more than rounding and are modelled here:
//  - shrink_chroma (YCoCg) sets the chroma extent to an eighth of the luma extent around the
//    current pixel, which can exceed the min/max chroma range; the checked box is the union.
//  - The output is stored through boundColor, which clamps negative RGB to 0. A YCoCg box
//    holds points with negative RGB, so a zero output channel may be the clamp of a negative
//    one: such a pixel is in bounds when some pre-clamp colour (that channel <= 0) is.
#include <algorithm>
#include <cmath>
#include <limits>

#include "invariants/invariant_support.h"

namespace taa::invariants {

namespace {

using namespace taa::spec;

constexpr double kHalfMax = 65504.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct Box {
  double lo[3];
  double hi[3];
};

void toWorking(const double rgb[3], bool ycocg, double w[3]) {
  if (!ycocg) {
    std::copy(rgb, rgb + 3, w);
    return;
  }
  w[0] = 0.25 * rgb[0] + 0.5 * rgb[1] + 0.25 * rgb[2];
  w[1] = 0.5 * rgb[0] - 0.5 * rgb[2];
  w[2] = -0.25 * rgb[0] + 0.5 * rgb[1] - 0.25 * rgb[2];
}

// RGB rows of the YCoCg -> RGB matrix: the most negative a channel gets inside a box.
double minRgbInBox(const Box& b, int channel) {
  static constexpr double kM[3][3] = {{1, 1, -1}, {1, 0, 1}, {1, -1, -1}};
  double m = 0.0;
  for (int j = 0; j < 3; ++j) m += kM[channel][j] * (kM[channel][j] > 0 ? b.lo[j] : b.hi[j]);
  return m;
}

double excessOf(const double rgb[3], const Box& b, bool ycocg) {
  double w[3];
  toWorking(rgb, ycocg, w);
  double e = 0.0;
  for (int k = 0; k < 3; ++k) e = std::max({e, b.lo[k] - w[k], w[k] - b.hi[k]});
  return e;
}

// Smallest excess over pre-clamp colours: channels zs[0..n) of `rgb` lowered by t in
// [0, limit]. The excess is convex in the lowered values, and so is its minimum over the
// inner channel, so nested golden-section searches find the minimum.
double coneExcess(double rgb[3], const int* zs, const double* limits, int n, const Box& b, bool ycocg) {
  if (n == 0) return excessOf(rgb, b, ycocg);
  const int k = zs[0];
  const double saved = rgb[k];
  auto f = [&](double t) {
    rgb[k] = saved - t;
    const double e = coneExcess(rgb, zs + 1, limits + 1, n - 1, b, ycocg);
    rgb[k] = saved;
    return e;
  };
  constexpr double kPhi = 0.6180339887498949;
  double a = 0.0, c = limits[0];
  double best = std::min(f(a), f(c));
  double x1 = c - kPhi * (c - a), x2 = a + kPhi * (c - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 48 && c - a > 1e-12; ++i) {
    if (f1 <= f2) {
      c = x2, x2 = x1, f2 = f1, x1 = c - kPhi * (c - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + kPhi * (c - a), f2 = f(x2);
    }
  }
  return std::min({best, f1, f2});
}

class HistoryBounded : public Invariant {
 public:
  explicit HistoryBounded(const CaseSpec& spec)
      : ycocg_(spec.taa.color_space == ColorSpace::YCoCg), shrinkChroma_(ycocg_ && spec.taa.shrink_chroma) {}

  void observe(const FrameView& f) override {
    if (!error_.empty() || f.historyReset) return;
    error_ = requireImage(f, f.output, "output", 3);
    if (error_.empty()) error_ = requireImage(f, f.current, "current", 3);
    if (!error_.empty()) return;
    ++framesChecked_;
    for (int y = 0; y < f.output->height; ++y)
      for (int x = 0; x < f.output->width; ++x) checkPixel(f, x, y);
  }

  Outcome finish() override {
    Outcome o{"history_bounded", false, "", {}};
    if (!error_.empty()) {
      o.detail = error_;
      return o;
    }
    o.values = {{"max_excess", worstExcess_}, {"tolerance", worstTol_},
                {"pixels_over", double(pixelsOver_)}, {"frames_checked", double(framesChecked_)},
                {"frame", worstFrame_}, {"x", worstX_}, {"y", worstY_}};
    const std::string where = " at frame " + std::to_string(worstFrame_) + " (" + std::to_string(worstX_) +
                              ", " + std::to_string(worstY_) + ")";
    if (framesChecked_ == 0) {
      o.detail = "no frame with history to check";
      return o;
    }
    o.passed = pixelsOver_ == 0;
    o.detail = o.passed ? "every output pixel inside its 3x3 box (largest excess " + num(worstExcess_) +
                              " <= tolerance " + num(worstTol_) + where + ")"
                        : std::to_string(pixelsOver_) + " pixel(s) outside the 3x3 box; worst excess " +
                              num(worstExcess_) + " > tolerance " + num(worstTol_) + where;
    return o;
  }

 private:
  void checkPixel(const FrameView& f, int x, int y) {
    const Image& cur = *f.current;
    Box b{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
    double centre[3] = {0, 0, 0}, sum[3] = {0, 0, 0};
    int valid = 0;
    bool centreValid = false;
    // Clamped addressing repeats edge taps, which cannot change a min/max: visit the
    // in-bounds neighbours only.
    for (int j = std::max(y - 1, 0); j <= std::min(y + 1, cur.height - 1); ++j)
      for (int i = std::max(x - 1, 0); i <= std::min(x + 1, cur.width - 1); ++i) {
        double c[3];
        bool nan = false;
        for (int k = 0; k < 3; ++k) {
          const double v = cur.at(i, j, k);
          nan = nan || std::isnan(v);
          c[k] = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, kHalfMax);
        }
        if (nan) continue;
        double w[3];
        toWorking(c, ycocg_, w);
        for (int k = 0; k < 3; ++k) {
          b.lo[k] = std::min(b.lo[k], w[k]);
          b.hi[k] = std::max(b.hi[k], w[k]);
          sum[k] += c[k];
        }
        ++valid;
        if (i == x && j == y) centreValid = true, std::copy(c, c + 3, centre);
      }
    if (valid == 0) std::fill(b.lo, b.lo + 3, 0.0), std::fill(b.hi, b.hi + 3, 0.0);
    if (shrinkChroma_ && valid > 0) {
      if (!centreValid)
        for (int k = 0; k < 3; ++k) centre[k] = sum[k] / valid;
      double wc[3];
      toWorking(centre, true, wc);
      const double e = 0.125 * (b.hi[0] - b.lo[0]);  // min/max luma extent >= the resolve's
      for (int k = 1; k < 3; ++k) b.lo[k] = std::min(b.lo[k], wc[k] - e), b.hi[k] = std::max(b.hi[k], wc[k] + e);
    }

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
    const double tol = std::ldexp(big, -10) + std::ldexp(boxBig, -20) + 1e-6;
    double e = finite ? excessOf(o, b, ycocg_) : kInf;
    if (finite && e > tol && ycocg_) e = std::min(e, clampedExcess(o, b));
    if (e > tol) ++pixelsOver_;
    if (e - tol > worstMargin_) {
      worstMargin_ = e - tol;
      worstExcess_ = e, worstTol_ = tol;
      worstFrame_ = f.frame, worstX_ = x, worstY_ = y;
    }
  }

  // Zero channels may be negatives clamped by boundColor. All three zero means black, and
  // black needs Y <= 0 with every channel <= 0, i.e. the point 0 itself: nothing to search.
  double clampedExcess(double o[3], const Box& b) const {
    int zs[3];
    double limits[3];
    int n = 0;
    for (int k = 0; k < 3; ++k)
      if (o[k] == 0.0 && minRgbInBox(b, k) < 0.0) zs[n] = k, limits[n] = -minRgbInBox(b, k), ++n;
    if (n == 0 || n == 3) return excessOf(o, b, true);
    return coneExcess(o, zs, limits, n, b, true);
  }

  bool ycocg_;
  bool shrinkChroma_;
  std::string error_;
  int framesChecked_ = 0;
  long long pixelsOver_ = 0;
  double worstMargin_ = -kInf, worstExcess_ = 0.0, worstTol_ = 0.0;
  int worstFrame_ = -1, worstX_ = -1, worstY_ = -1;
};

}  // namespace

std::string historyBoundedInapplicable(const CaseSpec& spec) {
  const std::string name = "history_bounded";
  const TaaSpec& t = spec.taa;
  auto because = [&](const std::string& why, const std::string& fix) {
    return name + " checks the clamp/clip box, but " + why + "; remove it from checks.invariants or " + fix;
  };
  if (t.mode != TaaMode::Full)
    return because(std::string("taa.mode is ") + enumToString(t.mode), "set taa.mode to full");
  if (t.rectify == Rectify::None) return because("taa.rectify is none", "enable taa.rectify");
  if (t.tonemap_weighting != ToneWeight::None && t.tonemap_weighting != ToneWeight::Karis)
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

std::unique_ptr<Invariant> makeHistoryBounded(const CaseSpec& spec) {
  return std::make_unique<HistoryBounded>(spec);
}

}  // namespace taa::invariants
