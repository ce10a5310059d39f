// OpenEXR encoding and decoding in memory with the OpenEXR library, for image_io.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/errors.h"
#include "core/image.h"

namespace taa::exr {

// A file OpenEXR cannot decode, or an image it cannot encode; what() is the reason without the
// file name (the caller adds it).
class ExrError : public InputError {
 public:
  using InputError::InputError;
};

bool hasExrMagic(std::string_view bytes);

// Encodes every channel (1 to 4, named R, G, B, A in that order) of `image` as a scanline
// OpenEXR with lossless ZIP compression, in half floats (the samples are rounded with
// floatToHalfBits) or 32-bit floats. The header holds only OpenEXR's required attributes (no
// date or software name), so the bytes depend only on the pixels and the library version.
std::string encode(const Image& image, bool halfFloat);

// Decodes the first part of a scanline or tiled OpenEXR (any pixel type) into float samples.
// Channels come in the order R, G, B, A (those present), then the others in the file's
// (alphabetical) order. The data window is read; its origin is dropped. Images with more than
// `maxSamples` samples, deep data and subsampled channels are refused, and so is every file
// whose length fields claim more bytes than it has (exrStructureProblem, before OpenEXR).
// With `layer`, channels are chosen by name instead: LAYER.R, .G, .B, .A ("R", "G", "B", "A"
// for an empty layer), those present in that order; a file without LAYER.R is refused
// naming its channels.
Image decode(std::string_view bytes, uint64_t maxSamples, const std::string* layer = nullptr);

}  // namespace taa::exr
