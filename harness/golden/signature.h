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

// The bounds within which two signatures count as the same frame rendered elsewhere; chosen
// from the suite under GALLIUM_OVERRIDE_CPU_CAPS=sse4.1 (docs: README, "Goldens").
inline constexpr int kSignatureCellTolerance = 3;             // 8-bit steps of a cell's mean luma
inline constexpr double kSignatureMeanTolerance = 1.0 / 255;  // a channel's frame mean

}  // namespace taa::golden
