#include "support/cpu_tscmaa.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/shared.h"
#include "support/noise.h"

namespace taa::test {

float tscmaaEdgeChannel(float c) {
  c = std::isnan(c) ? 0.0f : std::clamp(c, 0.0f, 65504.0f);
  const float mapped = c / (1.0f + c);
  return std::sqrt(mapped);
}

int tscmaaEdgeValue(const float a[3], const float b[3], float threshold) {
  const float dr = std::fabs(a[0] - b[0]), dg = std::fabs(a[1] - b[1]), db = std::fabs(a[2] - b[2]);
  const float diff = (0.2126f * dr + 0.7152f * dg) + 0.0722f * db;
  const float above = std::clamp(diff - threshold, 0.0f, 1.0f);
  const float scaled = above * 15.0f + 0.99f;
  return int(scaled);
}

bool tscmaaEdgeKept(const int values[12], float removal) {
  if (values[0] == 0) return false;
  int maxValue = 0, sum = 0;
  for (int i = 0; i < 12; ++i) {
    maxValue = std::max(maxValue, values[i]);
    sum += values[i];
  }
  const float threshold = float(sum) * (1.0f - removal) + float(12 * maxValue) * removal;
  return float(12 * values[0]) >= threshold;
}

uint32_t tscmaaTaaHash(uint32_t x, uint32_t y) {
  return hash32((x * 0x8da6b343u) ^ (y * 0xd8163841u)) & 0xffffu;
}

std::vector<uint32_t> tscmaaEdgeMask(const Image& color, const spec::TscmaaSpec& t, int offsetX) {
  const int w = color.width, h = color.height;
  auto index = [w](int x, int y) { return size_t(y) * size_t(w) + size_t(x); };
  std::vector<std::array<float, 3>> encoded(size_t(w) * size_t(h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        encoded[index(x, y)][size_t(c)] = tscmaaEdgeChannel(color.at(x, y, c));
  // The value of the edge right of and below every pixel; 0 at the image border.
  std::vector<int> right(encoded.size(), 0), below(encoded.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x + 1 < w)
        right[index(x, y)] = tscmaaEdgeValue(encoded[index(x, y)].data(),
                                             encoded[index(x + 1, y)].data(), t.edge_threshold);
      if (y + 1 < h)
        below[index(x, y)] = tscmaaEdgeValue(encoded[index(x, y)].data(),
                                             encoded[index(x, y + 1)].data(), t.edge_threshold);
    }
  auto at = [&](const std::vector<int>& e, int x, int y) {
    return x < 0 || y < 0 || x >= w || y >= h ? 0 : e[index(x, y)];
  };
  // The owner's twelve values, the judged edge first (as ownerKeeps in the shader).
  auto ownerKeeps = [&](int x, int y, bool isRight) {
    const int r = at(right, x, y), b = at(below, x, y);
    const int v[12] = {isRight ? r : b,     isRight ? b : r,         at(right, x + 1, y),
                       at(below, x + 1, y), at(right, x, y + 1),     at(below, x, y + 1),
                       at(right, x - 1, y), at(below, x - 1, y),     at(right, x, y - 1),
                       at(below, x, y - 1), at(below, x + 1, y - 1), at(right, x - 1, y + 1)};
    return tscmaaEdgeKept(v, t.non_dominant_edge_removal);
  };
  const auto share = uint32_t(std::lround(double(t.taa_share) * 65536.0));

  std::vector<uint32_t> mask(encoded.size(), 0u);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      uint32_t m = 0;
      if (ownerKeeps(x - 1, y, true)) m |= TSCMAA_EDGE_LEFT;
      if (ownerKeeps(x, y - 1, false)) m |= TSCMAA_EDGE_TOP;
      if (ownerKeeps(x, y, true)) m |= TSCMAA_EDGE_RIGHT;
      if (ownerKeeps(x, y, false)) m |= TSCMAA_EDGE_BOTTOM;
      if (m != 0u && tscmaaTaaHash(uint32_t(x + offsetX), uint32_t(y)) < share) m |= TSCMAA_TAA;
      mask[index(x, y)] = m;
    }
  return mask;
}

}  // namespace taa::test
