// A float image on the CPU: what readback produces and what the harness compares.
#pragma once

#include <cstddef>
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

// Rec. 709 luminance of an RGB(A) pixel.
inline float luminance(const Image& img, int x, int y) {
  return 0.2126f * img.at(x, y, 0) + 0.7152f * img.at(x, y, 1) + 0.0722f * img.at(x, y, 2);
}

}  // namespace taa
