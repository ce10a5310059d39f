#include "readback.h"

#include <Imath/half.h>

#include <cstring>
#include <stdexcept>

namespace taa {

namespace {

float halfAt(const uint8_t* p) {
  uint16_t bits;
  std::memcpy(&bits, p, 2);
  Imath::half h;
  h.setBits(bits);
  return float(h);
}

}  // namespace

Image decodeTarget(const std::vector<uint8_t>& bytes, VkFormat format, int targetWidth, int width, int height) {
  switch (format) {
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT: {
      const int channels = format == VK_FORMAT_R16G16_SFLOAT ? 2 : 4;
      Image out(width, height, channels);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
          for (int c = 0; c < channels; ++c)
            out.at(x, y, c) = halfAt(&bytes[(size_t(y) * targetWidth + x) * channels * 2 + size_t(c) * 2]);
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
      Image out(width, height, 2);
      for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
          uint32_t id;
          std::memcpy(&id, &bytes[(size_t(y) * targetWidth + x) * 4], 4);
          // Sky is all ones; report it as -1 in both channels.
          out.at(x, y, 0) = id == 0xffffffffu ? -1.0f : float(id >> 16);
          out.at(x, y, 1) = id == 0xffffffffu ? -1.0f : float(id & 0xffffu);
        }
      return out;
    }
    default:
      throw std::logic_error("decodeTarget: unhandled format " + std::to_string(int(format)));
  }
}

}  // namespace taa
