// Helpers for the post-pass tests: synthetic images, running one pass on them, and
// the measurements the tests compare.
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "core/image_io.h"
#include "passes/post_filter.h"
#include "support/gpu.h"

namespace taa::posttest {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// An RGBA image whose RGB is f(x, y) (grey) and alpha 1.
inline Image grey(int w, int h, const std::function<float(int, int)>& f) {
  Image img(w, h, 4, 1.0f);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = f(x, y);
  return img;
}

// Sets R, G and B (alpha stays as it is).
inline void setPixel(Image& img, int x, int y, float v) {
  for (int c = 0; c < 3; ++c) img.at(x, y, c) = v;
}

// What the GPU sees after an RGBA16F upload: every value rounded to half.
inline Image roundedToHalf(Image img) {
  for (float& v : img.data) v = halfRound(v);
  return img;
}

// Runs a filter pass (sharpen, CAS, FXAA) on `input` uploaded as RGBA16F.
template <class Pass>
Image runFilter(Pass& pass, const Image& input) {
  auto in = test::uploadFloatImage(input, VK_FORMAT_R16G16B16A16_SFLOAT);
  auto out = makePostImage(test::gpu(), "test_out", {input.width, input.height});
  VkCommandBuffer cmd = test::gpu().beginCommands();
  pass.record(cmd, in, out, {input.width, input.height});
  test::gpu().submitAndWait(cmd);
  return test::downloadImage(out);
}

inline bool pixelFinite(const Image& img, int x, int y) {
  for (int c = 0; c < img.channels; ++c)
    if (!std::isfinite(img.at(x, y, c))) return false;
  return true;
}

// Every pixel but those listed as (x, y) pairs in `skip` is finite.
inline int nonFiniteOutside(const Image& img, const std::vector<std::pair<int, int>>& skip) {
  int bad = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      bool skipped = false;
      for (const auto& s : skip) skipped |= s.first == x && s.second == y;
      if (!skipped && !pixelFinite(img, x, y)) ++bad;
    }
  return bad;
}

// Pixels (other than those in `skip`) whose bits differ between a and b.
inline int differingPixels(const Image& a, const Image& b,
                           const std::vector<std::pair<int, int>>& skip = {}) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      bool skipped = false;
      for (const auto& s : skip) skipped |= s.first == x && s.second == y;
      bool same = true;
      for (int c = 0; c < a.channels; ++c) same &= sameBits(a.at(x, y, c), b.at(x, y, c));
      n += !skipped && !same;
    }
  return n;
}

// Largest |difference| between horizontally adjacent pixels in row y (channel 0).
inline float maxStepInRow(const Image& img, int y) {
  float m = 0.0f;
  for (int x = 0; x + 1 < img.width; ++x)
    m = std::max(m, std::fabs(img.at(x + 1, y) - img.at(x, y)));
  return m;
}

}  // namespace taa::posttest
