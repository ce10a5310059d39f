#include "support/effects.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "support/gpu.h"

namespace taa::test {

spec::CaseSpec effectCase(const std::string& base, const std::string& patch) {
  nlohmann::json j = nlohmann::json::parse(base);
  j.merge_patch(nlohmann::json::parse(patch));
  return caseFromJson(j.dump(), "effect");
}

const EffectRun& renderOnce(const std::string& base, const std::string& patch,
                            const std::vector<int>& withImages, const RenderOptions& options) {
  static std::map<std::string, std::unique_ptr<EffectRun>> cache;
  std::string key = base + '\n' + patch + '\n';
  for (int f : withImages) key += std::to_string(f) + ',';
  for (const CaptureInfo& c : kCaptures) key += options.captures.has(c.capture) ? '1' : '0';
  key += options.hashEveryFrame ? 'h' : '-';
  auto& slot = cache[key];
  if (!slot) {
    auto run = std::make_unique<EffectRun>();
    run->spec = effectCase(base, patch);
    run->frames = renderCase(run->spec, withImages, options);
    slot = std::move(run);
  }
  return *slot;
}

void report(const std::string& what, double value) {
  std::printf("  [measured] %-58s %.6g\n", what.c_str(), value);
}


Mask fullMask(int width, int height) {
  return Mask(size_t(width) * size_t(height), true);
}

Mask rectMask(int width, int height, int x0, int y0, int x1, int y1) {
  return maskWhere(width, height,
                   [&](int x, int y) { return x >= x0 && x < x1 && y >= y0 && y < y1; });
}

Mask maskWhere(int width, int height, const std::function<bool(int, int)>& pred) {
  Mask m(size_t(width) * size_t(height));
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) m[size_t(y) * width + x] = pred(x, y);
  return m;
}

Mask maskAnd(const Mask& a, const Mask& b) {
  Mask m(a.size());
  for (size_t i = 0; i < a.size(); ++i) m[i] = a[i] && b[i];
  return m;
}

Mask maskNot(const Mask& a) {
  Mask m(a.size());
  for (size_t i = 0; i < a.size(); ++i) m[i] = !a[i];
  return m;
}

Mask dilate(const Mask& m, int width, int height, int radius) {
  return maskWhere(width, height, [&](int x, int y) {
    for (int j = std::max(0, y - radius); j <= std::min(height - 1, y + radius); ++j)
      for (int i = std::max(0, x - radius); i <= std::min(width - 1, x + radius); ++i)
        if (m[size_t(j) * width + i]) return true;
    return false;
  });
}

int count(const Mask& m) {
  return int(std::count(m.begin(), m.end(), true));
}

Mask moverMask(const FrameRecord& r) {
  const Image& ids = capturedImage(r, Capture::Ids);
  return maskWhere(ids.width, ids.height, [&](int x, int y) { return ids.at(x, y, 2) > 0.5f; });
}

namespace {

void checkShapes(const Image& a, const Image& b, const Mask& mask) {
  if (a.width != b.width || a.height != b.height || a.channels < 3 || b.channels < 3)
    throw std::invalid_argument("effect measure: images differ in size or have no RGB");
  if (!mask.empty() && mask.size() != a.pixelCount())
    throw std::invalid_argument("effect measure: mask size");
}

// Calls f(x, y) for every pixel the mask covers.
template <class F>
void forMasked(const Image& a, const Mask& mask, F f) {
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (mask.empty() || mask[size_t(y) * a.width + x]) f(x, y);
}

}  // namespace

double rmse(const Image& a, const Image& b, const Mask& mask) {
  checkShapes(a, b, mask);
  double sum = 0.0;
  size_t n = 0;
  forMasked(a, mask, [&](int x, int y) {
    for (int c = 0; c < 3; ++c) {
      const double d = double(a.at(x, y, c)) - double(b.at(x, y, c));
      sum += d * d;
      ++n;
    }
  });
  return n ? std::sqrt(sum / double(n)) : 0.0;
}

double meanAbs(const Image& a, const Image& b, const Mask& mask) {
  checkShapes(a, b, mask);
  double sum = 0.0;
  size_t n = 0;
  forMasked(a, mask, [&](int x, int y) {
    for (int c = 0; c < 3; ++c, ++n)
      sum += std::fabs(double(a.at(x, y, c)) - double(b.at(x, y, c)));
  });
  return n ? sum / double(n) : 0.0;
}

double maxAbs(const Image& a, const Image& b, const Mask& mask) {
  checkShapes(a, b, mask);
  double worst = 0.0;
  forMasked(a, mask, [&](int x, int y) {
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(double(a.at(x, y, c)) - double(b.at(x, y, c))));
  });
  return worst;
}

int differing(const Image& a, const Image& b, double tolerance, const Mask& mask) {
  checkShapes(a, b, mask);
  int n = 0;
  forMasked(a, mask, [&](int x, int y) {
    double d = 0.0;
    for (int c = 0; c < 3; ++c)
      d = std::max(d, std::fabs(double(a.at(x, y, c)) - double(b.at(x, y, c))));
    n += d > tolerance;
  });
  return n;
}

double localContrast(const Image& img, const Mask& mask) {
  double sum = 0.0;
  int n = 0;
  forMasked(img, mask, [&](int x, int y) {
    if (x == 0 || y == 0 || x == img.width - 1 || y == img.height - 1) return;
    const double around = 0.25 * (luminance(img, x - 1, y) + luminance(img, x + 1, y) +
                                  luminance(img, x, y - 1) + luminance(img, x, y + 1));
    sum += std::fabs(luminance(img, x, y) - around);
    ++n;
  });
  return n ? sum / n : 0.0;
}

Mask vacatedMask(const EffectRun& run, int from, int to) {
  const Mask now = moverMask(run[to]);
  const int w = run[to].color.width, h = run[to].color.height;
  Mask covered(now.size(), false);
  for (int f = from; f < to; ++f) {
    const Mask m = moverMask(run[f]);
    for (size_t i = 0; i < m.size(); ++i) covered[i] = covered[i] || m[i];
  }
  return maskAnd(covered, maskNot(dilate(now, w, h, 1)));
}

Mask silhouetteMask(const FrameRecord& r, int radius) {
  const Mask m = moverMask(r);
  const int w = r.color.width, h = r.color.height;
  return maskAnd(dilate(m, w, h, radius), dilate(maskNot(m), w, h, radius));
}

double meanFlicker(const EffectRun& run, int first, int last, const Mask& mask) {
  double sum = 0.0;
  for (int f = first + 1; f <= last; ++f) sum += meanAbs(run[f].color, run[f - 1].color, mask);
  return sum / double(last - first);
}

bool rgbIdentical(const Image& a, const Image& b) {
  if (!a.sameShape(b) || a.channels < 3) return false;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x)
      if (!sameRgbBits(a, b, x, y)) return false;
  return true;
}

bool allFiniteAtMost(const Image& img, float limit) {
  return std::all_of(img.data.begin(), img.data.end(),
                     [&](float v) { return std::isfinite(v) && v <= limit; });
}

Image bilinearUpscale(const Image& low, int width, int height) {
  Image out(width, height, low.channels);
  auto at = [&](int x, int y, int c) {
    return low.at(std::clamp(x, 0, low.width - 1), std::clamp(y, 0, low.height - 1), c);
  };
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const float sx = (x + 0.5f) * low.width / width - 0.5f,
                  sy = (y + 0.5f) * low.height / height - 0.5f;
      const int x0 = int(std::floor(sx)), y0 = int(std::floor(sy));
      const float fx = sx - x0, fy = sy - y0;
      for (int c = 0; c < low.channels; ++c)
        out.at(x, y, c) = (1 - fy) * ((1 - fx) * at(x0, y0, c) + fx * at(x0 + 1, y0, c)) +
                          fy * ((1 - fx) * at(x0, y0 + 1, c) + fx * at(x0 + 1, y0 + 1, c));
    }
  return out;
}

}  // namespace taa::test
