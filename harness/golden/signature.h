// A frame's quality signature: what a frame looks like, coarse enough not to depend on the
// machine's exact bits. Goldens store one per rendered frame so that on another CPU feature
// level or driver, where pixel hashes differ, frames without a stored EXR are still checked.
//
// The signature is taken on the display image the report shows (toDisplaySrgb: Reinhard, sRGB
// curve), so an HDR outlier counts at most as a white pixel:
//   - an 8 x 8 grid of cell means of the display luma (0.2126 R + 0.7152 G + 0.0722 B of the
//     sRGB-encoded values), each rounded to 8 bits: where in the frame something changed;
//   - the mean of each of R, G and B over the frame, rounded to 16 bits: colour shifts.
// Encoded as hex: 64 bytes of cells, then 3 big-endian 16-bit means (140 characters).
#pragma once

#include <string>

#include "core/image.h"

namespace taa::golden {

inline constexpr int kSignatureGrid = 8;

std::string frameSignature(const Image& hdr);

struct SignatureDistance {
  int cell = 0;        // the largest cell difference, in 8-bit steps (of 255)
  int cellIndex = 0;   // which cell: row * kSignatureGrid + column
  double mean = 0.0;   // the largest per-channel mean difference, in [0, 1]
  bool valid = false;  // false when either string is not a signature
};

SignatureDistance signatureDistance(const std::string& a, const std::string& b);

// The bounds within which two signatures count as the same frame rendered elsewhere. Measured
// over all 13,560 frames of the suite under GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 against goldens
// from x86-64-v4: cells differ by at most 1 step (rounding of a mean a hair from a step
// boundary), channel means by at most 6.1e-5. The bounds leave one step and 8x headroom; the
// mean bound stays below the 0.003 darkening that round-toward-zero history stores once caused.
inline constexpr int kSignatureCellTolerance = 2;        // 8-bit steps of a cell's mean luma
inline constexpr double kSignatureMeanTolerance = 5e-4;  // a channel's frame mean, in [0, 1]

}  // namespace taa::golden
