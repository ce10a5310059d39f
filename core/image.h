// A float image on the CPU: what readback produces and what the harness compares.
#pragma once

#include <cstddef>
#include <cstring>
#include <vector>

namespace taa {

// Row-major, top row first, channels interleaved.
struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;
  std::vector<float> data;

  Image() = default;
  Image(int w, int h, int c, float fill = 0.0f)
      : width(w), height(h), channels(c), data(size_t(w) * size_t(h) * size_t(c), fill) {}

  size_t index(int x, int y, int c = 0) const {
    return (size_t(y) * size_t(width) + size_t(x)) * size_t(channels) + size_t(c);
  }
  float& at(int x, int y, int c = 0) { return data[index(x, y, c)]; }
  float at(int x, int y, int c = 0) const { return data[index(x, y, c)]; }
  size_t pixelCount() const { return size_t(width) * size_t(height); }
  bool sameShape(const Image& o) const {
    return width == o.width && height == o.height && channels == o.channels;
  }
};

// Bit for bit, as goldens compare: == would call -0 and +0 equal and a NaN unequal to itself.
inline bool sameBits(float a, float b) {
  return std::memcmp(&a, &b, sizeof(float)) == 0;
}
inline bool sameBits(const Image& a, const Image& b) {
  return a.sameShape(b) &&
         std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(float)) == 0;
}
// The first three channels of pixel (x, y).
inline bool sameRgbBits(const Image& a, const Image& b, int x, int y) {
  return sameBits(a.at(x, y, 0), b.at(x, y, 0)) && sameBits(a.at(x, y, 1), b.at(x, y, 1)) &&
         sameBits(a.at(x, y, 2), b.at(x, y, 2));
}

// Rec. 709 luminance of an RGB(A) pixel.
inline float luminance(const Image& img, int x, int y) {
  return 0.2126f * img.at(x, y, 0) + 0.7152f * img.at(x, y, 1) + 0.0722f * img.at(x, y, 2);
}

}  // namespace taa
