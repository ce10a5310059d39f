// FXAA's tie-break when the edge mean rounds onto the centre's luma. With the
// neighbour across the edge one float ulp brighter (or darker) than the centre, and
// the centre's mantissa even, 0.5 * (lM + lS) rounds back to lM. Lottes' FXAA 3.11
// asks `lumaM - lumaNN * 0.5 < 0.0`, strictly: a centre on the mean counts as above
// it, the nearer end of the span (brighter than the mean here) runs the same way, the
// span is not good and the pixel keeps its colour. A `<=` there flips the span to
// good and blends a sixth of the way toward the neighbour.
//
// The lumas go through c / (1 + c), a dot product and a square root on the GPU, so
// the test does not rely on one pair landing one ulp apart: it builds every pair of
// half colours that a float model of the shader's luma puts one ulp apart, each in a
// tile of its own, and asserts that every tile's centre comes out bit-exact. The
// tile is built so that only the tie can move the centre: any other difference
// between the two lumas stops both searches at the first step (equal distances,
// offset 0), and sub-pixel removal is off.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <vector>

#include "passes/fxaa.h"
#include "renderer/post_test_util.h"

namespace taa::fxaa_tie_test {
namespace {

using namespace posttest;
using Rgb = std::array<float, 3>;

// The shader's luma, sqrt of Rec.601 luma of the tonemapped colour, in the two
// evaluation orders a compiler may give the dot product (plain or fused).
float lumaPlain(const Rgb& c) {
  float t[3];
  for (int i = 0; i < 3; ++i) t[i] = c[i] / (1.0f + c[i]);
  const float y = t[0] * 0.299f + t[1] * 0.587f + t[2] * 0.114f;
  return std::sqrt(y);
}

float lumaFused(const Rgb& c) {
  float t[3];
  for (int i = 0; i < 3; ++i) t[i] = c[i] / (1.0f + c[i]);
  return std::sqrt(std::fma(t[2], 0.114f, std::fma(t[1], 0.587f, t[0] * 0.299f)));
}

float halfUlp(float v) {
  int e = 0;
  std::frexp(v, &e);
  return std::ldexp(1.0f, e - 11);
}

// A grey whose luma is about `l`.
Rgb greyForLuma(float l) {
  const float t = l * l;
  const float c = halfRound(t / (1.0f - t));
  return {c, c, c};
}

bool evenMantissa(float v) {
  uint32_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  return (bits & 1u) == 0;
}

struct Pair {
  Rgb centre, across;
};

// Half colours `across` whose modelled luma is one ulp from `centre`'s in both
// evaluation orders, found by stepping red and green over the half lattice and
// solving for blue. The colours differ by many half steps, so a blend of a sixth
// between them shows in a half output.
std::vector<Pair> onePastPairs(const Rgb& centre) {
  std::vector<Pair> pairs;
  const float lM = lumaPlain(centre);
  if (lM != lumaFused(centre) || !evenMantissa(lM)) return pairs;
  const float yM = lM * lM;
  for (int i = -48; i <= 48; i += 3)
    for (int j = -24; j <= 24; j += 2) {
      Rgb c = centre;
      c[0] = halfRound(centre[0] + float(i) * halfUlp(centre[0]));
      c[1] = halfRound(centre[1] + float(j) * halfUlp(centre[1]));
      const float tr = c[0] / (1.0f + c[0]), tg = c[1] / (1.0f + c[1]);
      const float tb = (yM - 0.299f * tr - 0.587f * tg) / 0.114f;
      if (tb <= 0.0f || tb >= 0.9f) continue;
      const float b = halfRound(tb / (1.0f - tb));
      for (float db : {-1.0f, 0.0f, 1.0f}) {
        c[2] = halfRound(b + db * halfUlp(b));
        const float ulp = std::nextafter(lM, 2.0f) - lM;
        const float dP = lumaPlain(c) - lM, dF = lumaFused(c) - lM;
        if (dP == dF && std::fabs(dP) == ulp) pairs.push_back({centre, c});
      }
    }
  return pairs;
}

constexpr int kTileW = 4, kTileH = 3, kTilesPerRow = 16;

// One tile, columns x0..x0+3, rows y0..y0+2, centre at (x0 + 2, y0 + 1):
//   Q  NW  M  NE      M: the centre's colour, also north and west of it
//   Q  M   M  E       S: `across`, one ulp from M below the centre
//   Q  M   S  E       E: brighter by 0.2, NW brighter by 0.3, NE darker by 0.3, Q darker by 0.2
// The horizontal second derivatives (NW and NE against the rows) outweigh the
// vertical ones, so the span runs along the row and S is the side. The search's
// first tap west (the mean of M and M) equals the edge mean only in the tie, and the
// next one (Q) ends it; east, the mean of E and E ends it at once.
void drawTile(Image& img, int x0, int y0, const Pair& pair) {
  const float lM = lumaPlain(pair.centre);
  const Rgb e = greyForLuma(lM + 0.2f), q = greyForLuma(lM - 0.2f);
  const Rgb nw = greyForLuma(lM + 0.3f), ne = greyForLuma(lM - 0.3f);
  const Rgb& m = pair.centre;
  const Rgb tile[kTileH][kTileW] = {
      {q, nw, m, ne}, {q, m, m, e}, {q, m, pair.across, e}};
  for (int y = 0; y < kTileH; ++y)
    for (int x = 0; x < kTileW; ++x)
      for (int c = 0; c < 3; ++c) img.at(x0 + x, y0 + y, c) = tile[y][x][c];
}

TEST(FxaaTie, ACentreOnTheEdgeMeanCountsAsAboveItAsInLottesStrictTest) {
  std::vector<Pair> pairs;
  for (int k = 0; k < 64; ++k) {
    // Centres of luma near 0.5 with a tint, so that red and green have room to move.
    const float r = halfRound(0.22f + 0.004f * float(k)), g = halfRound(0.40f - 0.002f * float(k));
    const float b = halfRound(0.33f + 0.004f * float(k % 5));
    for (const Pair& p : onePastPairs({r, g, b})) pairs.push_back(p);
  }
  ASSERT_GE(pairs.size(), 64u) << "too few one-ulp pairs for the tie to be reached";

  const int rows = int((pairs.size() + kTilesPerRow - 1) / kTilesPerRow);
  Image in(kTilesPerRow * kTileW, rows * kTileH, 4, 1.0f);
  for (size_t i = 0; i < pairs.size(); ++i)
    drawTile(in, int(i % kTilesPerRow) * kTileW, int(i / kTilesPerRow) * kTileH, pairs[i]);
  // Tiles past the last pair repeat the first, so every tile is a well-formed one.
  for (size_t i = pairs.size(); i < size_t(rows * kTilesPerRow); ++i)
    drawTile(in, int(i % kTilesPerRow) * kTileW, int(i / kTilesPerRow) * kTileH, pairs[0]);

  FxaaSettings settings;
  settings.subpix = 0.0f;
  FxaaPass pass(test::gpu(), settings);
  const Image out = runFilter(pass, in);
  int moved = 0;
  for (int t = 0; t < rows * kTilesPerRow; ++t) {
    const int x = (t % kTilesPerRow) * kTileW + 2, y = (t / kTilesPerRow) * kTileH + 1;
    bool same = true;
    for (int c = 0; c < 4; ++c) same &= sameBits(out.at(x, y, c), in.at(x, y, c));
    moved += !same;
  }
  std::printf("%zu one-ulp pairs, %d centres moved\n", pairs.size(), moved);
  EXPECT_EQ(moved, 0);
}

}  // namespace
}  // namespace taa::fxaa_tie_test
