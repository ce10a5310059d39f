#include "compare/flip_common.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace taa::compare::flipdetail {

std::vector<CsfTerm> csfKernel(double ppd, std::initializer_list<std::pair<double, double>> ab) {
  const double maxB = 0.04;  // the widest of all three channels sets one common radius
  const double pi2 = std::numbers::pi * std::numbers::pi;
  const int r = int(std::ceil(3.0 * std::sqrt(maxB / (2.0 * pi2)) * ppd));
  std::vector<CsfTerm> terms;
  double total = 0.0;
  for (const auto& [a, b] : ab) {
    CsfTerm t;
    double sum = 0.0;
    for (int x = 0; x <= r; ++x) {
      const double deg = x / ppd;
      t.vertical.w.push_back(std::exp(-pi2 * deg * deg / b));
      sum += (x == 0 ? 1.0 : 2.0) * t.vertical.w.back();
    }
    const double s = a * std::sqrt(std::numbers::pi / b);
    total += s * sum * sum;
    t.horizontal.w = t.vertical.w;
    for (double& v : t.horizontal.w) v *= s;
    terms.push_back(std::move(t));
  }
  for (CsfTerm& t : terms) {
    for (double& v : t.horizontal.w) v /= total;
  }
  return terms;
}

// The 2D detectors are d(x) * e(y) with e > 0, so normalizing positive and negative 2D weights
// separately equals normalizing d's signed parts in 1D and e to sum 1.
FeatureKernels featureKernels(double ppd) {
  const double sd = 0.5 * kEdgePeakToTrough * ppd;
  const int r = int(std::ceil(3.0 * sd));
  FeatureKernels k;
  k.first.odd = true;
  k.second.zeroSum = true;
  double eSum = 0.0, firstSide = 0.0, secondPos = 0.0, secondNeg = 0.0;
  for (int x = 0; x <= r; ++x) {
    // x == 0 spelled out so a vanishing sigma (tiny ppd) cannot produce 0/0.
    const double x2 = double(x) * double(x);
    const double g = x == 0 ? 1.0 : std::exp(-x2 / (2.0 * sd * sd));
    const double second = ((x == 0 ? 0.0 : x2 / (sd * sd)) - 1.0) * g;
    const double mirrored = x == 0 ? 1.0 : 2.0;
    k.gauss.w.push_back(g);
    k.first.w.push_back(-x * g);
    k.second.w.push_back(second);
    eSum += mirrored * g;
    firstSide += x * g;  // both signs of the odd kernel have this magnitude
    (second > 0.0 ? secondPos : secondNeg) += mirrored * std::fabs(second);
  }
  for (double& v : k.gauss.w) v /= eSum;
  for (double& v : k.first.w) v = firstSide > 0.0 ? v / firstSide : 0.0;
  for (double& v : k.second.w) {
    const double d = v > 0.0 ? secondPos : secondNeg;
    v = d > 0.0 ? v / d : 0.0;
  }
  return k;
}

Kernels::Kernels(double ppd)
    : csf{csfKernel(ppd, {{1.0, 0.0047}}), csfKernel(ppd, {{1.0, 0.0053}}),
          csfKernel(ppd, {{34.1, 0.04}, {13.5, 0.025}})},
      features(featureKernels(ppd)) {}

namespace {

void mul3(const double m[3][3], const double in[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
}

double labF(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

}  // namespace

void huntLab(const double rgb[3], double out[3]) {
  double xyz[3];
  mul3(kRgbToXyz, rgb, xyz);
  const double fx = labF(xyz[0] / kWhite[0]);
  const double fy = labF(xyz[1] / kWhite[1]);
  const double fz = labF(xyz[2] / kWhite[2]);
  const double l = 116.0 * fy - 16.0;
  out[0] = l;
  out[1] = 0.01 * l * 500.0 * (fx - fy);
  out[2] = 0.01 * l * 200.0 * (fy - fz);
}

double hyab(const double a[3], const double b[3]) {
  const double da = a[1] - b[1];
  const double db = a[2] - b[2];
  return std::fabs(a[0] - b[0]) + std::sqrt(da * da + db * db);
}

double cmax() {
  const double green[3] = {0.0, 1.0, 0.0};
  const double blue[3] = {0.0, 0.0, 1.0};
  double g[3], b[3];
  huntLab(green, g);
  huntLab(blue, b);
  return std::pow(hyab(g, b), kQc);
}

void checkInputs(const Image& a, const Image& b, const FlipOptions& options) {
  if (!a.sameShape(b)) throw std::invalid_argument("flip: reference and test differ in shape");
  if (a.pixelCount() == 0 || a.channels <= 0) throw std::invalid_argument("flip: empty image");
  if (!(options.pixelsPerDegree > 0.0) || !std::isfinite(options.pixelsPerDegree)) {
    throw std::invalid_argument("flip: pixelsPerDegree must be positive and finite, got " +
                                std::to_string(options.pixelsPerDegree));
  }
}

void summarize(FlipResult& result) {
  const std::vector<float>& err = result.errorMap.data;
  double sum = 0.0;
  for (float e : err) sum += e;
  result.mean = sum / double(err.size());
  // Nearest rank: the value at sorted index ceil(p/100 * N) - 1. Each selection only searches
  // above the previous one, which nth_element has already partitioned off.
  std::vector<float> sorted = err;
  const size_t n = sorted.size();
  auto rankOf = [n](double percent) {
    const double rank = std::ceil(percent / 100.0 * double(n));
    return size_t(std::clamp(rank, 1.0, double(n))) - 1;
  };
  size_t from = 0;
  float* out[3] = {&result.p50, &result.p95, &result.p99};
  const double percents[3] = {50.0, 95.0, 99.0};
  for (int i = 0; i < 3; ++i) {
    const size_t k = std::max(rankOf(percents[i]), from);
    std::nth_element(sorted.begin() + std::ptrdiff_t(from), sorted.begin() + std::ptrdiff_t(k),
                     sorted.end());
    *out[i] = sorted[k];
    from = k;
  }
  result.max = *std::max_element(sorted.begin() + std::ptrdiff_t(from), sorted.end());
}

}  // namespace taa::compare::flipdetail
