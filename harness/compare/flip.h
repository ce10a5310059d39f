// LDR-FLIP: the perceptual difference evaluator of Andersson, Nilsson, Akenine-Moller, Oskarsson,
// Astrom and Fairchild, "FLIP: A Difference Evaluator for Alternating Images", HPG 2020.
// Written from the published algorithm; the structure follows NVlabs/flip's description of it.
//
// Per image (reference and test alike):
//   sRGB -> linear RGB -> XYZ (D65) -> YCxCz opponent space;
//   colour: each YCxCz channel is filtered with the paper's contrast sensitivity kernel
//     (sums of Gaussians a*sqrt(pi/b)*exp(-pi^2 r^2 / b), r in degrees; achromatic a=1 b=0.0047,
//     red-green a=1 b=0.0053, blue-yellow a1=34.1 b1=0.04 a2=13.5 b2=0.025; each kernel normalized
//     to sum 1 on a square of radius ceil(3 * sqrt(0.04 / (2 pi^2)) * ppd) pixels), back to linear
//     RGB, clamped to [0, 1], to CIELAB and Hunt-adjusted (a, b scaled by 0.01 L);
//   features: on the achromatic channel (relative luminance Y, which is what the paper's
//     (Y_YCxCz + 16) / 116 normalization gives) first and second x/y derivatives of a Gaussian
//     with sigma = 0.5 * 0.082 * ppd pixels, radius ceil(3 sigma), positive and negative weights
//     each normalized to sum +1 / -1.
// Per pixel:
//   colour error  dC = remap(HyAB(ref, test)^0.7), where remap sends [0, pc*cmax) linearly onto
//     [0, pt) and [pc*cmax, cmax] onto [pt, 1], pc = 0.4, pt = 0.95 and cmax = HyAB between
//     Hunt-adjusted pure green and pure blue, raised to 0.7;
//   feature error dF = (max(|edge_ref| - |edge_test|, |point_ref| - |point_test|) / sqrt 2)^0.5
//     with |.| the length of the (x, y) response and differences taken in absolute value;
//   FLIP = dC^(1 - dF), in [0, 1].
// Filters are correlations with clamp-to-edge borders, run as separable passes (the kernels are
// separable or sums of separable terms, so this equals the 2D filtering up to float rounding).
//
// flipLdr computes in float with the passes fused per row and rows split over threads
// (flip.cpp); every pixel's value is the same whatever the thread count. It agrees with the
// previous double implementation (flipLdrDouble, flip_double.h) within 1e-4 in the mean and 1e-3
// in any pixel (tests/compare/flip_fast_test.cpp), and with the pinned values of
// tests/compare/flip_reference.py to 1e-6.
//
// HDR-FLIP (Andersson, Nilsson, Shirley and Akenine-Moller, "Visualizing Errors in Rendered High
// Dynamic Range Images", Eurographics 2021), for linear frames: see flipHdr below.
#pragma once

#include "core/image.h"

namespace taa::compare {

// Pixels per degree of visual angle for a viewer `distanceM` metres from a screen `widthM` metres
// wide showing `widthPx` pixels across (small-angle form used by the paper).
double pixelsPerDegree(double distanceM, double widthM, int widthPx);

// 0.7 m from a 0.7 m wide 4K (3840 px) monitor: 3840 * pi / 180 = 67.02; the paper rounds it to
// 67. This is the exact value the reference implementation uses.
inline constexpr double kFlipDefaultPixelsPerDegree = 3840.0 * 3.14159265358979323846 / 180.0;

struct FlipOptions {
  double pixelsPerDegree = kFlipDefaultPixelsPerDegree;
  // Worker threads; 0 means one per hardware thread. Results are bit-identical for every count.
  int threads = 0;
};

struct FlipResult {
  // 1 channel, same size as the inputs, values in [0, 1]: filtered colours are clamped to the RGB
  // cube, where green-blue (cmax) is the largest Hunt-adjusted HyAB distance (checked on a 9^3
  // grid of the cube); like the reference, nothing clamps the result itself.
  Image errorMap;
  double mean = 0.0;  // mean of errorMap
  // Nearest-rank percentiles: the value at sorted index ceil(p/100 * N) - 1.
  float p50 = 0.0f;
  float p95 = 0.0f;
  float p99 = 0.0f;
  float max = 0.0f;
};

// LDR-FLIP between two display-referred sRGB-encoded images. RGB is read from the first three
// channels (1- and 2-channel images count as grey); alpha is ignored. Samples are clamped to
// [0, 1] and NaN counts as 0. Throws std::invalid_argument for empty or differently shaped images
// or a pixelsPerDegree that is not positive and finite.
FlipResult flipLdr(const Image& referenceSrgb, const Image& testSrgb,
                   const FlipOptions& options = {});

// LDR-FLIP for linear HDR frames: both go through taa::toDisplaySrgb (per-channel Reinhard
// c / (1 + c), negatives to 0, +Inf to 1, NaN pixels magenta, then the sRGB curve; the exact
// mapping of the PNGs people look at), then flipLdr. Values above 1 are compressed, not clipped,
// so highlight differences still register, but more weakly than HDR-FLIP would weigh them.
FlipResult flipLdrFromHdr(const Image& referenceHdr, const Image& testHdr,
                          const FlipOptions& options = {});

struct HdrFlipResult : FlipResult {
  double startExposure = 0.0;  // log2 exposure of the first and last LDR-FLIP pass
  double stopExposure = 0.0;
  int exposures = 0;
};

// HDR-FLIP between two linear (scene-referred) images, as the paper defines it:
//   luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the reference's pixels (non-finite ones
//   skipped); x85 the input at which the ACES curve (Narkowicz's fit with the paper's 0.6
//   pre-exposure folded in) reaches 0.85; start = log2(x85 / Ymax), stop = log2(x85 / Ymedian)
//   (median: the element at index N/2 of the sorted luminances); N = max(2, ceil(stop - start))
//   exposures c_i evenly spaced from start to stop;
//   per exposure: both images times 2^c_i, ACES per channel, clamped to [0, 1], taken as linear
//   RGB into LDR-FLIP (no sRGB decode); the HDR-FLIP error is the per-pixel maximum over the N
//   LDR-FLIP maps.
// Where the paper leaves cases open: negative samples count as 0; a NaN in any channel makes the
// pixel magenta at every exposure (as the PNGs show it); +Inf saturates. If Ymedian is 0 (more
// than half the reference black) the smallest positive luminance stands in; if Ymax is 0 or no
// pixel is finite, one exposure at 0 is used (start = stop = 0, N = 1).
HdrFlipResult flipHdr(const Image& referenceLinear, const Image& testLinear,
                      const FlipOptions& options = {});

}  // namespace taa::compare
