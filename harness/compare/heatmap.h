// Pictures of differences for reports: a colour-mapped error heatmap, zoomed crops for A/B
// viewing, and the location of the worst region so the crop lands where it matters.
#pragma once

#include <array>

#include "core/image.h"

namespace taa::compare {

// The magma colour map (matplotlib, CC0) from 9 of its 256 entries (indices 0, 32, ..., 224, 255)
// treated as evenly spaced and interpolated linearly in display (sRGB-encoded) space. Luminance
// rises strictly from near-black through purple and orange to pale yellow, so brighter always
// means more error, also in greyscale print. t is clamped to [0, 1]; NaN gives the NaN colour.
std::array<float, 3> magma(float t);

// Pure green: outside magma's hues, so pixels whose error is undefined stand out.
inline constexpr std::array<float, 3> kHeatmapNanColour = {0.0f, 1.0f, 0.0f};

// A display-referred RGB image in [0, 1] (write it with writePngLinear8) from channel 0 of an
// error map. Linear scale: error 0 -> magma(0), error >= maxError -> magma(1), so the same
// maxError across frames keeps colours comparable. Use maxError 1 for FLIP maps (their range);
// for absolute-error maps pick the tolerance of interest. +Inf maps to magma(1), NaN to
// kHeatmapNanColour. Throws std::invalid_argument unless maxError is positive and finite.
Image heatmap(const Image& errorMap, float maxError = 1.0f);

// The w x h rectangle at (x, y), all channels. Throws std::out_of_range unless it lies inside
// the image and is not empty.
Image crop(const Image& image, int x, int y, int w, int h);

// Every pixel repeated factor x factor times, so zoomed crops show pixels, not blur.
// Throws std::invalid_argument for factor < 1.
Image upscaleNearest(const Image& image, int factor);

struct Region {
  int x = 0;
  int y = 0;
  int width = 0;  // the window actually used (clamped to the image)
  int height = 0;
  double sum = 0.0;  // summed error in the window, in the quantized units below
};

// The w x h window (clamped to the image size) of channel 0 with the largest summed error, via a
// summed-area table. Sums are exact so ties are real ties, broken toward the smallest y, then the
// smallest x: each value is quantized to a multiple of 2^-20 and capped at 65536, negative values
// count as 0 and NaN/Inf as the cap, and the table is 64-bit integers (exact for images up to
// 2^26 pixels). Throws std::invalid_argument for an empty map or w, h < 1.
Region worstRegion(const Image& errorMap, int w, int h);

}  // namespace taa::compare
