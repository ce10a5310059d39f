// The pixel fingerprint stored in golden manifests: SHA-256 over the image's
// samples converted to IEEE half floats (little-endian, row-major, channels
// interleaved). Frames come from RGBA16F targets, so the conversion is exact and
// the hash equals that of the bytes the GPU wrote.
#pragma once

#include <string>

#include "core/image.h"

namespace taa {

std::string pixelSha256(const Image& image);

}  // namespace taa
