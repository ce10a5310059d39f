#include "frame/readback.h"

#include <array>
#include <cstring>
#include <stdexcept>

#include "common/shared.h"
#include "core/image_io.h"

namespace taa {

namespace {

// halfBitsToFloat of every half, looked up: every frame of every case is read back in halves,
// and the table (256 KiB, filled once) decodes them several times faster, to the same bits.
const std::array<float, 65536>& halfTable() {
  static const auto table = [] {
    std::array<float, 65536> t;
    for (uint32_t h = 0; h < t.size(); ++h) t[h] = halfBitsToFloat(uint16_t(h));
    return t;
  }();
  return table;
}

}  // namespace

Image decodeTarget(const uint8_t* bytes, VkFormat format, int targetWidth, int width, int height) {
  switch (format) {
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT: {
      const int channels = format == VK_FORMAT_R16G16_SFLOAT ? 2 : 4;
      Image out(width, height, channels);
      const auto& table = halfTable();
      const size_t row = size_t(width) * size_t(channels);
      for (int y = 0; y < height; ++y) {
        const uint8_t* in = &bytes[size_t(y) * size_t(targetWidth) * size_t(channels) * 2];
        float* dst = &out.at(0, y);
        for (size_t i = 0; i < row; ++i) {
          uint16_t bits;
          std::memcpy(&bits, in + 2 * i, 2);
          dst[i] = table[bits];
        }
      }
      return out;
    }
    case VK_FORMAT_R32G32B32A32_SFLOAT: {
      Image out(width, height, 4);
      for (int y = 0; y < height; ++y)
        std::memcpy(&out.at(0, y), &bytes[size_t(y) * targetWidth * 16], size_t(width) * 16);
      return out;
    }
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_R32_SFLOAT: {
      Image out(width, height, 1);
      for (int y = 0; y < height; ++y)
        std::memcpy(&out.at(0, y), &bytes[size_t(y) * targetWidth * 4], size_t(width) * 4);
      return out;
    }
    case VK_FORMAT_R32_UINT: {
      Image out(width, height, 3);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          uint32_t id;
          std::memcpy(&id, &bytes[(size_t(y) * targetWidth + x) * 4], 4);
          const bool sky = id == IDS_SKY;
          out.at(x, y, 0) = sky ? -1.0f : float((id >> 16) & 0x7fffu);
          out.at(x, y, 1) = sky ? -1.0f : float(id & 0xffffu);
          out.at(x, y, 2) = (id & IDS_MOVER_BIT) ? 1.0f : 0.0f;
        }
      return out;
    }
    default:
      throw std::logic_error("decodeTarget: unhandled format " + std::to_string(int(format)));
  }
}

}  // namespace taa
