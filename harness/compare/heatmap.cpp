#include "compare/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace taa::compare {

namespace {

// matplotlib's magma at indices 0, 32, 64, 96, 128, 160, 192, 224 and 255.
constexpr float kMagma[9][3] = {
    {0.001462f, 0.000466f, 0.013866f}, {0.113094f, 0.065492f, 0.276784f},
    {0.316654f, 0.071690f, 0.485380f}, {0.512831f, 0.148179f, 0.507648f},
    {0.716387f, 0.214982f, 0.475290f}, {0.904281f, 0.319610f, 0.388137f},
    {0.986700f, 0.535582f, 0.382210f}, {0.996898f, 0.769591f, 0.534892f},
    {0.987053f, 0.991438f, 0.749504f}};

constexpr double kQuantum = 1048576.0;  // 2^20 steps per unit of error
constexpr double kCap = 65536.0;

int64_t quantize(float v) {
  if (std::isnan(v) || v >= kCap) return int64_t(kCap * kQuantum);
  if (!(v > 0.0f)) return 0;
  return std::llround(double(v) * kQuantum);
}

}  // namespace

std::array<float, 3> magma(float t) {
  if (std::isnan(t)) return kHeatmapNanColour;
  const float s = std::clamp(t, 0.0f, 1.0f) * 8.0f;
  const int k = std::min(int(s), 7);
  const float f = s - float(k);
  std::array<float, 3> c;
  for (int i = 0; i < 3; ++i) c[size_t(i)] = kMagma[k][i] + (kMagma[k + 1][i] - kMagma[k][i]) * f;
  return c;
}

Image heatmap(const Image& errorMap, float maxError) {
  if (!(maxError > 0.0f) || std::isinf(maxError)) {
    throw std::invalid_argument("heatmap: maxError must be positive and finite");
  }
  if (errorMap.channels < 1 && errorMap.pixelCount() > 0) {
    throw std::invalid_argument("heatmap: error map has no channels");
  }
  Image out(errorMap.width, errorMap.height, 3);
  for (int y = 0; y < errorMap.height; ++y) {
    for (int x = 0; x < errorMap.width; ++x) {
      const float v = errorMap.at(x, y, 0);
      // Inf / maxError is Inf, which magma clamps to 1; NaN passes through to the NaN colour.
      const auto c = magma(v / maxError);
      for (int i = 0; i < 3; ++i) out.at(x, y, i) = c[size_t(i)];
    }
  }
  return out;
}

Image crop(const Image& image, int x, int y, int w, int h) {
  if (w < 1 || h < 1 || x < 0 || y < 0 || x > image.width - w || y > image.height - h) {
    throw std::out_of_range("crop: " + std::to_string(w) + "x" + std::to_string(h) + " at (" +
                            std::to_string(x) + ", " + std::to_string(y) + ") is not inside a " +
                            std::to_string(image.width) + "x" + std::to_string(image.height) +
                            " image");
  }
  Image out(w, h, image.channels);
  const size_t rowFloats = size_t(w) * size_t(image.channels);
  for (int row = 0; row < h; ++row) {
    const auto src = image.data.begin() + std::ptrdiff_t(image.index(x, y + row));
    std::copy(src, src + std::ptrdiff_t(rowFloats),
              out.data.begin() + std::ptrdiff_t(out.index(0, row)));
  }
  return out;
}

Image upscaleNearest(const Image& image, int factor) {
  if (factor < 1) throw std::invalid_argument("upscaleNearest: factor must be at least 1");
  Image out(image.width * factor, image.height * factor, image.channels);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < image.channels; ++c)
        out.at(x, y, c) = image.at(x / factor, y / factor, c);
    }
  }
  return out;
}

Region worstRegion(const Image& errorMap, int w, int h) {
  if (errorMap.pixelCount() == 0 || errorMap.channels < 1) {
    throw std::invalid_argument("worstRegion: empty error map");
  }
  if (w < 1 || h < 1) throw std::invalid_argument("worstRegion: window must be at least 1x1");
  w = std::min(w, errorMap.width);
  h = std::min(h, errorMap.height);
  const int W = errorMap.width;
  const int H = errorMap.height;
  // sat[(y)(W+1) + x] = sum of the map over [0, x) x [0, y).
  std::vector<int64_t> sat(size_t(W + 1) * size_t(H + 1), 0);
  auto at = [&](int x, int y) -> int64_t& { return sat[size_t(y) * size_t(W + 1) + size_t(x)]; };
  for (int y = 0; y < H; ++y) {
    int64_t rowSum = 0;
    for (int x = 0; x < W; ++x) {
      rowSum += quantize(errorMap.at(x, y, 0));
      at(x + 1, y + 1) = at(x + 1, y) + rowSum;
    }
  }
  Region best{0, 0, w, h, -1.0};
  int64_t bestSum = -1;
  for (int y = 0; y + h <= H; ++y) {
    for (int x = 0; x + w <= W; ++x) {
      const int64_t s = at(x + w, y + h) - at(x, y + h) - at(x + w, y) + at(x, y);
      if (s > bestSum) {  // strict: the first (smallest y, then x) of equal sums wins
        bestSum = s;
        best.x = x;
        best.y = y;
      }
    }
  }
  best.sum = double(bestSum) / kQuantum;
  return best;
}

}  // namespace taa::compare
