#include "scene/textures.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

namespace taa::scene {
namespace {

const std::array<double, 256>& srgbTable() {
  static const std::array<double, 256> table = [] {
    std::array<double, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgbToLinear(i / 255.0);
    return t;
  }();
  return table;
}

// Integer overlap weights of a box reduction from `src` to `dst` texels: destination
// texel d covers [d * src, (d + 1) * src) and source texel s covers [s * dst, (s + 1) *
// dst), both in units of 1 / (src * dst). Integers keep the filter exact and
// order-independent; the weights of one destination texel sum to `src`.
struct Tap {
  int source;
  int weight;
};
std::vector<std::vector<Tap>> boxTaps(int src, int dst) {
  std::vector<std::vector<Tap>> taps(static_cast<size_t>(dst));
  for (int d = 0; d < dst; ++d) {
    const long lo = long(d) * src;
    const long hi = lo + src;
    for (int s = int(lo / dst); s < src && long(s) * dst < hi; ++s) {
      const long overlap = std::min(hi, long(s + 1) * dst) - std::max(lo, long(s) * dst);
      if (overlap > 0) taps[size_t(d)].push_back({s, int(overlap)});
    }
  }
  return taps;
}

Texture::Level reduce(const Texture::Level& src, bool linear) {
  Texture::Level dst;
  dst.width = std::max(1, src.width / 2);
  dst.height = std::max(1, src.height / 2);
  const auto tx = boxTaps(src.width, dst.width);
  const auto ty = boxTaps(src.height, dst.height);
  const auto& lut = srgbTable();
  // Horizontal pass into linear doubles, then vertical pass and re-encode.
  std::vector<double> row(size_t(dst.width) * size_t(src.height) * 4);
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < dst.width; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0.0;
        for (const Tap& t : tx[size_t(x)]) {
          const uint8_t v =
              src.rgba[(size_t(y) * size_t(src.width) + size_t(t.source)) * 4 + size_t(c)];
          sum += t.weight * (c < 3 && !linear ? lut[v] : v / 255.0);
        }
        row[(size_t(y) * size_t(dst.width) + size_t(x)) * 4 + size_t(c)] = sum;
      }
  const double norm = double(src.width) * double(src.height);
  dst.rgba.resize(size_t(dst.width) * size_t(dst.height) * 4);
  for (int y = 0; y < dst.height; ++y)
    for (int x = 0; x < dst.width; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0.0;
        for (const Tap& t : ty[size_t(y)])
          sum += t.weight * row[(size_t(t.source) * size_t(dst.width) + size_t(x)) * 4 + size_t(c)];
        const double v = sum / norm;
        dst.rgba[(size_t(y) * size_t(dst.width) + size_t(x)) * 4 + size_t(c)] =
            c < 3 && !linear ? linearToSrgb8(v)
                             : uint8_t(std::lround(std::clamp(v, 0.0, 1.0) * 255.0));
      }
  return dst;
}

float smooth(float t) {
  return t * t * (3.0f - 2.0f * t);
}

int wrap(int i, int period) {
  return ((i % period) + period) % period;
}

// Tileable value noise: `px` x `py` lattice cells across the texture.
float valueNoise(float u, float v, int px, int py, uint32_t seed) {
  const float x = u * float(px), y = v * float(py);
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = smooth(x - float(x0)), fy = smooth(y - float(y0));
  auto at = [&](int i, int j) {
    return hashUnit(hash3(uint32_t(wrap(i, px)), uint32_t(wrap(j, py)), seed));
  };
  const float a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * fx;
  const float b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * fx;
  return a + (b - a) * fy;
}

uint8_t mix8(uint8_t a, uint8_t b, float t) {
  const float v = float(a) + (float(b) - float(a)) * std::clamp(t, 0.0f, 1.0f);
  return uint8_t(std::clamp(int(std::lround(v)), 0, 255));
}

Rgba8 mix(Rgba8 a, Rgba8 b, float t) {
  return {mix8(a[0], b[0], t), mix8(a[1], b[1], t), mix8(a[2], b[2], t), mix8(a[3], b[3], t)};
}

template <class F>
Texture generate(int size, F texel) {
  std::vector<uint8_t> rgba(size_t(size) * size_t(size) * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Rgba8 c = texel(x, y);
      std::copy(c.begin(), c.end(),
                rgba.begin() + std::ptrdiff_t((size_t(y) * size_t(size) + size_t(x)) * 4));
    }
  return makeTexture(size, size, std::move(rgba));
}

}  // namespace

double srgbToLinear(double e) {
  return e <= 0.04045 ? e / 12.92 : std::pow((e + 0.055) / 1.055, 2.4);
}

double linearToSrgb(double l) {
  return l <= 0.0031308 ? l * 12.92 : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

double srgb8ToLinear(uint8_t code) {
  return srgbTable()[code];
}

uint8_t linearToSrgb8(double linear) {
  return uint8_t(
      std::lround(std::clamp(linearToSrgb(std::clamp(linear, 0.0, 1.0)), 0.0, 1.0) * 255.0));
}

uint32_t hash32(uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint32_t hash3(uint32_t x, uint32_t y, uint32_t seed) {
  return hash32(x ^ hash32(y ^ hash32(seed + 0x9e3779b9U)));
}

float hashUnit(uint32_t h) {
  return float(h >> 8) * (1.0f / 16777216.0f);
}

void generateMips(Texture& texture) {
  assert(!texture.levels.empty());
  texture.levels.resize(1);
  while (texture.levels.back().width > 1 || texture.levels.back().height > 1)
    texture.levels.push_back(reduce(texture.levels.back(), texture.linear));
}

Texture makeTexture(int width, int height, std::vector<uint8_t> rgba, TextureSampler sampler,
                    bool linear) {
  assert(width > 0 && height > 0 && rgba.size() == size_t(width) * size_t(height) * 4);
  Texture t;
  t.sampler = sampler;
  t.linear = linear;
  t.levels.push_back({width, height, std::move(rgba)});
  generateMips(t);
  return t;
}

bool hasTranslucentTexels(const Texture& texture) {
  if (texture.levels.empty()) return false;
  const auto& px = texture.levels[0].rgba;
  for (size_t i = 3; i < px.size(); i += 4)
    if (px[i] < 255) return true;
  return false;
}

Texture checkerTexture(int size, int cells, Rgba8 a, Rgba8 b) {
  return generate(size, [&](int x, int y) {
    return ((x * cells / size) + (y * cells / size)) % 2 == 0 ? a : b;
  });
}

Texture leafTexture(int size, uint32_t seed) {
  struct Leaf {
    float bx, by, dx, dy, length, width;
    Rgba8 color;
  };
  // Leaves alternate along a vertical stem, pointing outwards and up (image y grows down).
  // Directions come from hashed vectors normalised with sqrt: no libm trigonometry, so
  // the texels do not depend on the platform's sin/cos.
  constexpr int kLeaves = 9;
  std::vector<Leaf> leaves;
  for (int i = 0; i < kLeaves; ++i) {
    const float h1 = hashUnit(hash3(uint32_t(i), 1, seed));
    const float h2 = hashUnit(hash3(uint32_t(i), 2, seed));
    const float h3 = hashUnit(hash3(uint32_t(i), 3, seed));
    const bool top = i == kLeaves - 1;
    const float side = top ? 0.0f : (i % 2 == 0 ? -1.0f : 1.0f);
    float dx = side * (0.5f + 0.5f * h1), dy = -(0.35f + 0.65f * h2);
    const float len = std::sqrt(dx * dx + dy * dy);
    dx /= len;
    dy /= len;
    const float by = top ? 0.2f : 0.88f - 0.68f * float(i) / float(kLeaves - 1);
    const Rgba8 color{uint8_t(48 + int(40 * h3)), uint8_t(96 + int(50 * h1)),
                      uint8_t(28 + int(24 * h2)), 255};
    leaves.push_back({0.5f, by, dx, dy, 0.24f + 0.12f * h3, 0.07f + 0.03f * h2, color});
  }
  const Rgba8 clear{64, 112, 40, 0};
  const Rgba8 stem{92, 70, 40, 255};
  return generate(size, [&](int x, int y) {
    const float px = (float(x) + 0.5f) / float(size), py = (float(y) + 0.5f) / float(size);
    for (const Leaf& l : leaves) {
      const float ox = px - l.bx, oy = py - l.by;
      const float u = ox * l.dx + oy * l.dy;   // along the leaf
      const float v = -ox * l.dy + oy * l.dx;  // across it
      if (u < 0.0f || u > l.length) continue;
      const float r = u / l.length;
      const float half = l.width * 4.0f * r * (1.0f - r);  // pointed at both ends
      if (std::fabs(v) > half) continue;
      // A lighter midrib and darker tip keep some detail for the mips to average.
      if (std::fabs(v) < 0.006f) return mix(l.color, Rgba8{180, 200, 120, 255}, 0.5f);
      return mix(l.color, Rgba8{20, 50, 15, 255}, 0.4f * r);
    }
    if (std::fabs(px - 0.5f) < 0.012f && py > 0.1f && py < 0.97f) return stem;
    return clear;
  });
}

Texture roughNoiseTexture(int size, uint32_t seed) {
  const Rgba8 dark{22, 20, 19, 255}, bright{238, 226, 204, 255};
  return generate(size, [&](int x, int y) {
    const float u = (float(x) + 0.5f) / float(size), v = (float(y) + 0.5f) / float(size);
    const float white = hashUnit(hash3(uint32_t(x), uint32_t(y), seed));
    const float coarse = valueNoise(u, v, 8, 8, seed + 1);
    const float fine = valueNoise(u, v, 32, 32, seed + 2);
    float t = 0.45f * white + 0.35f * fine + 0.2f * coarse;
    t = (t - 0.5f) * 1.9f + 0.5f;
    if (hashUnit(hash3(uint32_t(x), uint32_t(y), seed + 3)) < 0.02f) t = 1.0f;  // sparkles
    Rgba8 c = mix(dark, bright, t);
    const float tint = hashUnit(hash3(uint32_t(x), uint32_t(y), seed + 4)) - 0.5f;
    c[0] = uint8_t(std::clamp(int(c[0]) + int(tint * 40.0f), 0, 255));
    c[2] = uint8_t(std::clamp(int(c[2]) - int(tint * 40.0f), 0, 255));
    return c;
  });
}

Texture groundTexture(int size, uint32_t seed, Rgba8 dark, Rgba8 bright) {
  return generate(size, [&](int x, int y) {
    const float u = (float(x) + 0.5f) / float(size), v = (float(y) + 0.5f) / float(size);
    const float white = hashUnit(hash3(uint32_t(x), uint32_t(y), seed)) - 0.5f;
    const float t =
        0.6f * valueNoise(u, v, 8, 8, seed + 1) + 0.4f * valueNoise(u, v, 32, 32, seed + 2);
    return mix(dark, bright, t + 0.15f * white);
  });
}

Texture woodTexture(int size, uint32_t seed) {
  const Rgba8 dark{118, 80, 46, 255}, light{178, 128, 78, 255};
  return generate(size, [&](int x, int y) {
    const float u = (float(x) + 0.5f) / float(size), v = (float(y) + 0.5f) / float(size);
    const float grain = valueNoise(u, v, 16, 2, seed);
    const float white = hashUnit(hash3(uint32_t(x), uint32_t(y), seed + 1)) - 0.5f;
    return mix(dark, light, grain + 0.1f * white);
  });
}

}  // namespace taa::scene
