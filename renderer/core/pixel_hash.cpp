#include "core/pixel_hash.h"

#include <Imath/half.h>

#include <cstdint>
#include <vector>

#include "core/sha256.h"

namespace taa {

std::string pixelSha256(const Image& image) {
  std::vector<uint8_t> bytes(image.data.size() * 2);
  for (size_t i = 0; i < image.data.size(); ++i) {
    const uint16_t bits = Imath::half(image.data[i]).bits();
    bytes[2 * i] = uint8_t(bits & 0xff);
    bytes[2 * i + 1] = uint8_t(bits >> 8);
  }
  return sha256Hex(bytes.data(), bytes.size());
}

}  // namespace taa
