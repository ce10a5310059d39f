// Frames come back from the device as halves: decodeTarget's table must give, for every one of
// the 65536 half patterns, what halfBitsToFloat gives, in rows with padding.
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <vector>

#include "core/image_io.h"
#include "frame/readback.h"

namespace taa::readback_decode_test {
namespace {

constexpr int kRowPixels = 128, kRowStride = 131, kRows = 128;  // 128 x 128 x 4 = every half once

std::vector<uint8_t> everyHalfPadded() {
  std::vector<uint8_t> bytes(size_t(kRowStride) * kRows * 4 * 2, 0xab);
  uint32_t h = 0;
  for (int y = 0; y < kRows; ++y)
    for (int i = 0; i < kRowPixels * 4; ++i, ++h) {
      const uint16_t bits = uint16_t(h * 40503u);  // an odd multiplier visits every pattern
      std::memcpy(&bytes[(size_t(y) * kRowStride * 4 + size_t(i)) * 2], &bits, 2);
    }
  return bytes;
}

TEST(ReadbackDecode, EveryHalfDecodesAsHalfBitsToFloat) {
  const auto bytes = everyHalfPadded();
  const Image img =
      decodeTarget(bytes, VK_FORMAT_R16G16B16A16_SFLOAT, kRowStride, kRowPixels, kRows);
  ASSERT_EQ(img.channels, 4);
  for (int y = 0; y < kRows; ++y)
    for (int i = 0; i < kRowPixels * 4; ++i) {
      uint16_t bits;
      std::memcpy(&bits, &bytes[(size_t(y) * kRowStride * 4 + size_t(i)) * 2], 2);
      const float want = halfBitsToFloat(bits);
      ASSERT_EQ(std::bit_cast<uint32_t>(img.data[size_t(y) * kRowPixels * 4 + size_t(i)]),
                std::bit_cast<uint32_t>(want))
          << "half 0x" << std::hex << bits;
    }
}

}  // namespace
}  // namespace taa::readback_decode_test
