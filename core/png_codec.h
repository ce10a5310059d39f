// PNG encoding and decoding in memory with libpng, for image_io. Kept apart from the file
// handling so that an encoding error and a file-system error stay distinguishable.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/errors.h"
#include "core/image.h"

namespace taa::png {

// A file that is not a PNG libpng can decode, or an image it cannot encode; what() is libpng's
// reason without the file name (the caller adds it).
class PngError : public InputError {
 public:
  using InputError::InputError;
};

// zlib level of every PNG the harness writes. Measured on rendered frames and FLIP heatmaps
// (docs/performance.md, "PNG and EXR writing"): level 2 costs a quarter of the default 6's time
// for files 16% larger; lower levels grow the files faster than they save time.
inline constexpr int kZlibLevel = 2;

bool hasPngSignature(std::string_view bytes);

// Encodes `width` x `height` pixels of 1 (grey) or 3 (RGB) interleaved 8-bit samples, rows top
// first, as an 8-bit PNG with no ancillary chunks (no time stamp: the bytes depend only on the
// pixels and the level).
std::string encode8(const uint8_t* samples, int width, int height, int channels, int zlibLevel);

// Decodes any PNG (grey, grey + alpha, RGB, RGBA, palette; 1 to 16 bits; interlaced or not)
// into float samples in [0, 1]: value / 255 or value / 65535 with no transfer function applied
// and alpha left unassociated, as stored. Palettes become RGB, transparency chunks an alpha
// channel, low bit depths 8-bit. Images with more than `maxSamples` samples are refused.
Image decode(std::string_view bytes, uint64_t maxSamples);

}  // namespace taa::png
