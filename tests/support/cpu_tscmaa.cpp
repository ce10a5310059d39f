#include "support/cpu_tscmaa.h"

#include <algorithm>
#include <cmath>

#include "common/shared.h"

namespace taa::test {

namespace {

float scrub(float c) {
  return std::isnan(c) ? 0.0f : std::clamp(c, 0.0f, 65504.0f);
}

float max6(float a, float b, float c, float d, float e, float f) {
  return std::max(std::max(std::max(a, b), std::max(c, d)), std::max(e, f));
}

}  // namespace

float tscmaaEdgeLuma(float r, float g, float b) {
  r = scrub(r);
  g = scrub(g);
  b = scrub(b);
  const float y = (0.2126f * r + 0.7152f * g) + 0.0722f * b;
  const float mapped = y / (1.0f + y);
  return std::sqrt(mapped);
}

bool tscmaaEdgeKept(float e, float m, float threshold, float removal) {
  const float lowered = e - removal * std::max(m - e, 0.0f);
  return lowered > threshold;
}

uint32_t tscmaaTaaHash(uint32_t x, uint32_t y) {
  uint32_t h = (x * 0x8da6b343u) ^ (y * 0xd8163841u);
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h & 0xffffu;
}

std::vector<uint32_t> tscmaaEdgeMask(const Image& color, const spec::TscmaaSpec& t, int offsetX) {
  const int w = color.width, h = color.height;
  std::vector<float> luma(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      luma[size_t(y) * size_t(w) + size_t(x)] =
          tscmaaEdgeLuma(color.at(x, y, 0), color.at(x, y, 1), color.at(x, y, 2));
  auto at = [&](int x, int y) {
    return x < 0 || y < 0 || x >= w || y >= h ? -1.0f : luma[size_t(y) * size_t(w) + size_t(x)];
  };
  auto diff = [](float a, float b) { return a < 0.0f || b < 0.0f ? 0.0f : std::fabs(a - b); };
  auto hEdge = [&](int x, int y) { return diff(at(x, y), at(x + 1, y)); };  // right of (x, y)
  auto vEdge = [&](int x, int y) { return diff(at(x, y), at(x, y + 1)); };  // below (x, y)
  auto kept = [&](float e, float m) {
    return tscmaaEdgeKept(e, m, t.edge_threshold, t.non_dominant_edge_removal);
  };
  const auto share = uint32_t(std::lround(double(t.taa_share) * 65536.0));

  std::vector<uint32_t> mask(luma.size(), 0u);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float l = hEdge(x - 1, y), tp = vEdge(x, y - 1), r = hEdge(x, y), b = vEdge(x, y);
      const float lt = hEdge(x - 1, y - 1), lb = hEdge(x - 1, y + 1), rt = hEdge(x, y - 1),
                  rb = hEdge(x, y + 1);
      const float tl = vEdge(x - 1, y - 1), tr = vEdge(x + 1, y - 1), bl = vEdge(x - 1, y),
                  br = vEdge(x + 1, y);
      uint32_t m = 0;
      if (kept(l, max6(lt, lb, tl, tp, bl, b))) m |= TSCMAA_EDGE_LEFT;
      if (kept(tp, max6(tl, tr, lt, l, rt, r))) m |= TSCMAA_EDGE_TOP;
      if (kept(r, max6(rt, rb, tp, tr, b, br))) m |= TSCMAA_EDGE_RIGHT;
      if (kept(b, max6(bl, br, l, lb, r, rb))) m |= TSCMAA_EDGE_BOTTOM;
      if (m != 0u && tscmaaTaaHash(uint32_t(x + offsetX), uint32_t(y)) < share) m |= TSCMAA_TAA;
      mask[size_t(y) * size_t(w) + size_t(x)] = m;
    }
  return mask;
}

}  // namespace taa::test
