// The constants, filter kernels and result statistics of LDR-FLIP (see flip.h for the algorithm),
// shared by the fast float implementation (flip.cpp) and the double one it is checked against
// (flip_double.cpp). Weights are computed in double; the float code rounds them once.
#pragma once

#include <initializer_list>
#include <utility>
#include <vector>

#include "compare/flip.h"

namespace taa::compare::flipdetail {

// Constants of the paper (section 3) and its supplementary material.
inline constexpr double kQc = 0.7;  // colour error exponent
// The feature exponent qf = 0.5 appears as a square root.
inline constexpr double kPc = 0.4;                  // share of cmax mapped onto [0, pt)
inline constexpr double kPt = 0.95;                 // error value at pc * cmax
inline constexpr double kEdgePeakToTrough = 0.082;  // degrees; twice the detector's sigma

// D65 white in XYZ and the sRGB primaries' matrices (exact rational forms of IEC 61966-2-1).
inline constexpr double kWhite[3] = {0.950428545, 1.0, 1.088900371};
inline constexpr double kRgbToXyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};
inline constexpr double kXyzToRgb[3][3] = {{3.241003275, -1.537398934, -0.498615861},
                                           {-0.969224334, 1.875930071, 0.041554224},
                                           {0.055639423, -0.204011202, 1.057148933}};

// A centred kernel that is even (k(-i) = k(i)) or odd (k(-i) = -k(i)), stored from its centre
// outwards. Every FLIP filter is one or the other, and folding the mirrored taps halves the
// multiplications. Odd kernels sum to zero by construction; `zeroSum` marks an even one that does
// in exact arithmetic (the second-derivative detector): it is applied as
// sum_i k(i) * ((in(x + i) - in(x)) + (in(x - i) - in(x))), which is the same filter but gives
// exactly zero on flat input. That matters because FLIP takes the square root of feature
// differences and would turn a rounding residue into a visible error.
struct Kernel {
  std::vector<double> w;  // w[i]: weight at offset +i
  bool odd = false;
  bool zeroSum = false;
  int radius() const { return int(w.size()) - 1; }
};

// dst[x] = sum_i k(i) * at(i)[x] for i in [-r, r] (a correlation), where at(i) is the source
// row shifted by i; in the kernel's precision T (double for the reference, float for the fast
// path). Taps are accumulated over the whole row (outer loop over taps) so the inner loops
// vectorize. K is Kernel or a kernel of T with the same members.
template <class T, class K, class At>
void applyKernel(const K& k, int n, At at, T* dst) {
  const T* c = at(0);
  const T w0 = k.odd || k.zeroSum ? T(0) : T(k.w[0]);
  for (int x = 0; x < n; ++x) dst[x] = w0 * c[x];
  for (int i = 1; i <= k.radius(); ++i) {
    const T* plus = at(i);
    const T* minus = at(-i);
    const T wi = T(k.w[size_t(i)]);
    if (k.odd) {
      for (int x = 0; x < n; ++x) dst[x] += wi * (plus[x] - minus[x]);
    } else if (k.zeroSum) {
      for (int x = 0; x < n; ++x) dst[x] += wi * ((plus[x] - c[x]) + (minus[x] - c[x]));
    } else {
      for (int x = 0; x < n; ++x) dst[x] += wi * (plus[x] + minus[x]);
    }
  }
}

struct CsfTerm {
  Kernel horizontal;  // carries the term's weight and the kernel's normalization
  Kernel vertical;
};

// The contrast sensitivity kernel of one opponent channel as separable terms. The 2D kernel is
// sum_i a_i sqrt(pi/b_i) g_i(x) g_i(y) / S, with g_i(x) = exp(-pi^2 (x/ppd)^2 / b_i) and S its
// sum over the square of radius ceil(3 * sqrt(0.04 / (2 pi^2)) * ppd), so each term factors into a
// row and a column pass. Every channel has that one radius (set by the widest, b = 0.04).
std::vector<CsfTerm> csfKernel(double ppd, std::initializer_list<std::pair<double, double>> ab);

struct FeatureKernels {
  Kernel gauss;   // normalized to sum 1
  Kernel first;   // positive weights sum to 1, negative to -1
  Kernel second;  // likewise
};

// Gaussian, first and second derivative with sigma = 0.5 * 0.082 * ppd, radius ceil(3 sigma).
FeatureKernels featureKernels(double ppd);

struct Kernels {
  std::vector<CsfTerm> csf[3];  // achromatic, red-green, blue-yellow
  FeatureKernels features;
  explicit Kernels(double ppd);
};

// Linear RGB to Hunt-adjusted CIELAB (a and b scaled by 0.01 L).
void huntLab(const double rgb[3], double out[3]);
double hyab(const double a[3], const double b[3]);
// HyAB between Hunt-adjusted pure green and pure blue, raised to qc.
double cmax();

// Throws std::invalid_argument for empty or differently shaped images or a bad pixelsPerDegree.
void checkInputs(const Image& a, const Image& b, const FlipOptions& options);

// Fills mean (a sum in pixel order, in double) and the nearest-rank percentiles from errorMap.
void summarize(FlipResult& result);

}  // namespace taa::compare::flipdetail
