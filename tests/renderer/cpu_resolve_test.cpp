// Properties of the resolve's formulas, checked on the CPU mirror (support/cpu_resolve), which
// the ResolveAgreement tests tie to the shader. Each property is what the technique promises,
// so a wrong formula in the shader shows up here once the mirror agrees with it.
#include "support/cpu_resolve.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "support/noise.h"

namespace taa {
namespace {

using glm::vec2;
using glm::vec3;
using test::hashUnit;
namespace cpu = test::cpu;

vec3 randomColor(uint32_t seed, int i, float scale) {
  return scale * vec3(hashUnit(seed, i, 0, 0), hashUnit(seed, i, 0, 1), hashUnit(seed, i, 0, 2));
}

// A 3x3 neighbourhood of colours in [0, 8) in working space (all valid).
cpu::Neighborhood randomNeighborhood(uint32_t seed, int i, bool yCoCg) {
  cpu::Neighborhood n;
  for (int k = 0; k < 9; ++k) {
    n.taps[k] = cpu::toWorking(randomColor(seed, i * 9 + k, 8.0f), yCoCg);
    n.valid[k] = true;
  }
  return n;
}

// The box clip works against: widened in every channel by one half-float step of its
// largest bound, so a converged history rounded into a half is not pulled inwards.
cpu::Box clipBox(const cpu::Box& b) {
  const vec3 bound = glm::max(glm::abs(b.lo), glm::abs(b.hi));
  const float margin = std::max(bound.x, std::max(bound.y, bound.z)) / 1024.0f;
  cpu::Box w = b;
  w.lo -= vec3(margin);
  w.hi += vec3(margin);
  return w;
}

bool inside(vec3 p, const cpu::Box& b, float eps) {
  for (int c = 0; c < 3; ++c)
    if (p[c] < b.lo[c] - eps || p[c] > b.hi[c] + eps) return false;
  return true;
}

TEST(CpuResolve, BoxIsTheMinMaxOfTheNeighborhoodAndClampStaysInside) {
  spec::TaaSpec taa;
  taa.color_space = spec::ColorSpace::Rgb;
  int moved = 0;
  for (int i = 0; i < 2000; ++i) {
    const cpu::Neighborhood n = randomNeighborhood(1, i, false);
    const cpu::Box b = cpu::neighborhoodBox(n, n.taps[4], taa);
    for (int c = 0; c < 3; ++c) {
      float lo = n.taps[0][c], hi = n.taps[0][c];
      for (const vec3& t : n.taps) lo = std::min(lo, t[c]), hi = std::max(hi, t[c]);
      ASSERT_EQ(b.lo[c], lo);
      ASSERT_EQ(b.hi[c], hi);
    }
    const vec3 h = randomColor(2, i, 10.0f) - 1.0f;  // often outside the box
    const vec3 r = cpu::clampToBox(h, b);
    ASSERT_TRUE(inside(r, b, 0.0f));
    // Clamping is per channel: a channel already inside keeps its value.
    for (int c = 0; c < 3; ++c) {
      if (h[c] >= b.lo[c] && h[c] <= b.hi[c]) {
        ASSERT_EQ(r[c], h[c]);
      }
    }
    moved += r != h;
  }
  EXPECT_GT(moved, 500);  // the test saw real clamping
}

TEST(CpuResolve, ClipLandsOnTheSegmentToTheBoxCentreAndInsideTheBox) {
  spec::TaaSpec taa;
  for (bool yCoCg : {false, true}) {
    taa.color_space = yCoCg ? spec::ColorSpace::YCoCg : spec::ColorSpace::Rgb;
    int clipped = 0;
    for (int i = 0; i < 2000; ++i) {
      const cpu::Neighborhood n = randomNeighborhood(3, i, yCoCg);
      const cpu::Box b = cpu::neighborhoodBox(n, n.taps[4], taa);
      const vec3 h = cpu::toWorking(randomColor(4, i, 12.0f) - 2.0f, yCoCg);
      const vec3 r = cpu::clipToBox(h, b);
      const vec3 centre = 0.5f * (b.lo + b.hi);
      const cpu::Box wb = clipBox(b);
      ASSERT_TRUE(inside(r, wb, 1e-5f)) << "i " << i;
      if (inside(h, wb, 0.0f)) {
        ASSERT_EQ(r, h);  // inside the box, history is kept as is
        continue;
      }
      ++clipped;
      // r = centre + s (h - centre) with one s in (0, 1] for all three channels...
      const vec3 d = h - centre;
      const int major = std::abs(d.x) >= std::abs(d.y) && std::abs(d.x) >= std::abs(d.z) ? 0
                        : std::abs(d.y) >= std::abs(d.z)                                 ? 1
                                                                                         : 2;
      const float s = (r[major] - centre[major]) / d[major];
      ASSERT_GT(s, 0.0f);
      ASSERT_LE(s, 1.0f + 1e-6f);
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(r[c], centre[c] + s * d[c], 1e-5f) << "i " << i;
      // ...and it stops on the box's surface, not short of it: the closest point of the segment.
      float surface = 0.0f;
      for (int c = 0; c < 3; ++c)
        surface = std::max(surface, std::abs(r[c] - centre[c]) / (0.5f * (wb.hi[c] - wb.lo[c])));
      ASSERT_NEAR(surface, 1.0f, 1e-5f);
    }
    EXPECT_GT(clipped, 500);
  }
}

TEST(CpuResolve, VarianceBoxLiesWithinMeanPlusMinusGammaSigmaAndTheMinMaxBox) {
  for (float gamma : {0.0f, 0.5f, 0.75f, 1.0f, 2.0f}) {
    spec::TaaSpec taa;
    taa.color_space = spec::ColorSpace::Rgb;
    taa.variance_clip = true;
    taa.variance_gamma = gamma;
    spec::TaaSpec plain = taa;
    plain.variance_clip = false;
    int tighter = 0;
    for (int i = 0; i < 1000; ++i) {
      const cpu::Neighborhood n = randomNeighborhood(5, i, false);
      const cpu::Box b = cpu::neighborhoodBox(n, n.taps[4], taa);
      const cpu::Box minMax = cpu::neighborhoodBox(n, n.taps[4], plain);
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0, sum2 = 0.0;
        for (const vec3& t : n.taps) sum += t[c], sum2 += double(t[c]) * t[c];
        const double mean = sum / 9.0, sigma = std::sqrt(std::max(sum2 / 9.0 - mean * mean, 0.0));
        const double eps = 1e-5 * (1.0 + std::abs(mean));
        ASSERT_GE(b.lo[c], mean - gamma * sigma - eps);
        ASSERT_LE(b.hi[c], mean + gamma * sigma + eps);
        ASSERT_GE(b.lo[c], minMax.lo[c]);
        ASSERT_LE(b.hi[c], minMax.hi[c]);
        ASSERT_LE(b.lo[c], b.hi[c]);
        // Where mean - gamma sigma is inside the min/max box it is the bound, not looser.
        if (mean - gamma * sigma > minMax.lo[c]) {
          ASSERT_NEAR(b.lo[c], mean - gamma * sigma, eps);
        }
        tighter += b.lo[c] > minMax.lo[c];
      }
      const vec3 h = randomColor(6, i, 12.0f) - 2.0f;
      ASSERT_TRUE(inside(cpu::clipToBox(h, b), clipBox(b), 1e-5f));
    }
    if (gamma <= 1.0f) {
      EXPECT_GT(tighter, 1000) << "gamma " << gamma;
    }
  }
}

TEST(CpuResolve, ShapedNeighborhoodAveragesTheBoxAndTheCross) {
  spec::TaaSpec taa;
  taa.color_space = spec::ColorSpace::Rgb;
  taa.shaped_neighborhood = true;
  for (int i = 0; i < 500; ++i) {
    const cpu::Neighborhood n = randomNeighborhood(7, i, false);
    const cpu::Box b = cpu::neighborhoodBox(n, n.taps[4], taa);
    for (int c = 0; c < 3; ++c) {
      float lo = 1e30f, hi = -1e30f, crossLo = 1e30f, crossHi = -1e30f;
      for (int k = 0; k < 9; ++k) {
        lo = std::min(lo, n.taps[k][c]), hi = std::max(hi, n.taps[k][c]);
        if (k == 1 || k == 3 || k == 4 || k == 5 || k == 7)
          crossLo = std::min(crossLo, n.taps[k][c]), crossHi = std::max(crossHi, n.taps[k][c]);
      }
      ASSERT_FLOAT_EQ(b.lo[c], 0.5f * (lo + crossLo));
      ASSERT_FLOAT_EQ(b.hi[c], 0.5f * (hi + crossHi));
    }
  }
}

TEST(CpuResolve, ShrinkChromaCentresChromaOnTheCurrentPixelAtAQuarterOfTheLumaExtent) {
  spec::TaaSpec taa;
  taa.color_space = spec::ColorSpace::YCoCg;
  taa.shrink_chroma = true;
  for (int i = 0; i < 500; ++i) {
    const cpu::Neighborhood n = randomNeighborhood(8, i, true);
    const cpu::Box b = cpu::neighborhoodBox(n, n.taps[4], taa);
    const float lumaExtent = b.hi.x - b.lo.x;
    for (int c = 1; c < 3; ++c) {
      ASSERT_FLOAT_EQ(0.5f * (b.lo[c] + b.hi[c]), n.taps[4][c]);
      ASSERT_NEAR(b.hi[c] - b.lo[c], 0.25f * lumaExtent, 1e-5f);
    }
  }
}

TEST(CpuResolve, YCoCgRoundTripIsExactTo1e6) {
  EXPECT_EQ(cpu::rgbToYCoCg(vec3(1.0f)), vec3(1.0f, 0.0f, 0.0f));  // grey has no chroma
  EXPECT_EQ(cpu::rgbToYCoCg(vec3(1.0f, 0.0f, 0.0f)), vec3(0.25f, 0.5f, -0.25f));
  EXPECT_EQ(cpu::rgbToYCoCg(vec3(0.0f, 1.0f, 0.0f)), vec3(0.5f, 0.0f, 0.5f));
  for (int i = 0; i < 10000; ++i) {
    const float scale = i % 3 == 0 ? 1.0f : i % 3 == 1 ? 1e3f : cpu::kHalfMax;
    const vec3 c = randomColor(9, i, scale);
    const vec3 r = cpu::yCoCgToRgb(cpu::rgbToYCoCg(c));
    const float m = std::max({c.x, c.y, c.z, 1.0f});
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(r[k], c[k], 1e-6f * m) << c[k];
  }
}

// ---- dynamic alpha and tone-weighted blends ----

TEST(CpuResolve, LottesAlphaStaysWithinAlphaMinAndAlphaMax) {
  const float aMin = 0.04f, aMax = 0.2f;
  const float lumas[] = {0.0f, 1e-3f, 0.1f, 0.2f, 0.5f, 1.0f, 5.0f, 1e3f, 65504.0f};
  for (float a : lumas)
    for (float b : lumas) {
      const float alpha = cpu::lottesAlpha(a, b, aMin, aMax);
      ASSERT_GE(alpha, aMin) << a << " " << b;
      ASSERT_LE(alpha, aMax) << a << " " << b;
    }
  // A stable pixel leans on history; a pixel that changed completely trusts the current frame.
  EXPECT_EQ(cpu::lottesAlpha(3.0f, 3.0f, aMin, aMax), aMin);
  EXPECT_FLOAT_EQ(cpu::lottesAlpha(0.0f, 2.0f, aMin, aMax), aMax);
  // Lottes' weight is the squared similarity 1 - |dL| / max(L, 0.2): here 1 - 0.5 / 1.5.
  const double s = 2.0 / 3.0;
  EXPECT_NEAR(cpu::lottesAlpha(1.0f, 1.5f, aMin, aMax), aMax + (aMin - aMax) * s * s, 1e-7);
  // Below 0.2 the floor keeps dark pixels from reading as completely changed.
  EXPECT_NEAR(cpu::lottesAlpha(0.0f, 0.1f, aMin, aMax), aMax + (aMin - aMax) * 0.25, 1e-7);
  // In between, alpha grows with the relative luma difference.
  float previous = aMin;
  for (float h = 1.0f; h <= 2.0f; h += 0.0625f) {
    const float alpha = cpu::lottesAlpha(1.0f, h, aMin, aMax);
    ASSERT_GE(alpha, previous);
    previous = alpha;
  }
  EXPECT_GT(previous, aMin + 0.5f * (aMax - aMin));
}

TEST(CpuResolve, ReduceBlendNearClampLowersAlphaTowardTheBoxEdge) {
  const float alpha = 0.1f, lo = 1.0f, hi = 3.0f;
  EXPECT_FLOAT_EQ(cpu::reduceBlendNearClamp(alpha, 2.0f, lo, hi), alpha);  // centre: unchanged
  // Halfway from the centre to the edge, a quarter less.
  EXPECT_FLOAT_EQ(cpu::reduceBlendNearClamp(alpha, 1.5f, lo, hi), 0.75f * alpha);
  const float edge = 0.5f * alpha;
  EXPECT_FLOAT_EQ(cpu::reduceBlendNearClamp(alpha, lo, lo, hi), edge);
  EXPECT_FLOAT_EQ(cpu::reduceBlendNearClamp(alpha, 5.0f, lo, hi), edge);      // beyond: as the edge
  EXPECT_FLOAT_EQ(cpu::reduceBlendNearClamp(alpha, 1.0f, 1.0f, 1.0f), edge);  // flat box
  float previous = 0.0f;
  for (float h = lo; h <= 2.0f; h += 0.125f) {
    const float a = cpu::reduceBlendNearClamp(alpha, h, lo, hi);
    ASSERT_GE(a, previous);
    previous = a;
  }
}

// Two small HDR frames for whole-resolve properties.
Image smallHdr(uint32_t seed, float scale) {
  Image img(16, 12, 4, 1.0f);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = scale * hashUnit(seed, x, y, c);
  return img;
}

TEST(CpuResolve, AlphaOneReturnsTheCurrentFrame) {
  const Image current = smallHdr(10, 8.0f), history = smallHdr(11, 1e3f);
  const cpu::CpuResolveInputs in{current, history, {0.25f, -0.75f}};
  spec::TaaSpec taa;
  taa.velocity_sampling = spec::VelocitySampling::Pixel;
  taa.alpha = 1.0f;
  taa.color_space = spec::ColorSpace::Rgb;  // YCoCg round-trips the current colour (1e-7)
  const Image out = cpu::cpuResolve(in, taa);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(out.at(x, y, c), current.at(x, y, c));
  // The weighted blends map the current colour there and back: equal up to float rounding.
  for (auto w : {spec::ToneWeight::Karis, spec::ToneWeight::InverseLuma, spec::ToneWeight::Log}) {
    taa.tonemap_weighting = w;
    taa.color_space = spec::ColorSpace::YCoCg;
    const Image weighted = cpu::cpuResolve(in, taa);
    for (size_t i = 0; i < weighted.data.size(); ++i)
      ASSERT_NEAR(weighted.data[i], current.data[i], 2e-6f * std::max(current.data[i], 1.0f));
  }
}

TEST(CpuResolve, KarisWeightingLimitsASingleBrightSample) {
  const vec3 history(1.0f), firefly(1000.0f);
  const float alpha = 0.1f;
  const vec3 plain = cpu::toneWeightedBlend(history, firefly, alpha, spec::ToneWeight::None);
  const vec3 karis = cpu::toneWeightedBlend(history, firefly, alpha, spec::ToneWeight::Karis);
  EXPECT_NEAR(plain.x, 100.9f, 1e-3f);  // the firefly drags plain blending far from history
  // Weights alpha / (1 + luma): (0.1 * 1000 / 1001 + 0.9 / 2) / (0.1 / 1001 + 0.9 / 2).
  const double wc = 0.1 / 1001.0, wh = 0.9 / 2.0;
  EXPECT_NEAR(karis.x, (1000.0 * wc + wh) / (wc + wh), 1e-4);
  EXPECT_LT(karis.x - history.x, 0.01f * (plain.x - history.x));
  // Equal colours blend to themselves, whatever the weights.
  const vec3 c(2.0f, 0.5f, 7.0f);
  const vec3 same = cpu::toneWeightedBlend(c, c, 0.3f, spec::ToneWeight::Karis);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(same[k], c[k], 1e-6f * c[k]);
}

TEST(CpuResolve, InverseLumaBlendStaysFiniteNearThePoleAndUpToHalfMax) {
  // Blending a grey with itself: the tonemapped luma g / (1 + g) runs up to the pole at 1.
  for (float g = 1.0f; g <= cpu::kHalfMax; g *= 1.5f) {
    const vec3 r = cpu::toneWeightedBlend(vec3(g), vec3(g), 0.1f, spec::ToneWeight::InverseLuma);
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE(std::isfinite(r[k])) << g;
      ASSERT_NEAR(r[k], g, 0.01f * g) << g;
    }
  }
  const vec3 top = cpu::toneWeightedBlend(vec3(cpu::kHalfMax), vec3(cpu::kHalfMax), 0.5f,
                                          spec::ToneWeight::InverseLuma);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(top[k], cpu::kHalfMax, 0.01f * cpu::kHalfMax);
  // Mixed colours from 0 to half max: finite, non-negative, luma between the two lumas.
  const float values[] = {0.0f, 1e-3f, 1.0f, 100.0f, 1e4f, cpu::kHalfMax};
  for (float a : values)
    for (float b : values)
      for (float c : values)
        for (float alpha : {0.0f, 0.1f, 0.5f, 1.0f}) {
          const vec3 h(a, b, c), cur(c, a, b);
          const vec3 r = cpu::toneWeightedBlend(h, cur, alpha, spec::ToneWeight::InverseLuma);
          for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(r[k]) && r[k] >= 0.0f);
          const float lh = cpu::luma(h), lc = cpu::luma(cur), lr = cpu::luma(r);
          ASSERT_GE(lr, std::min(lh, lc) * (1.0f - 1e-2f) - 1e-6f);
          ASSERT_LE(lr, std::max(lh, lc) * (1.0f + 1e-2f) + 1e-6f);
        }
}

// What a YCoCg box can hand back next to a magenta firefly (see resolve_tone_weight_test):
// negative green, luma about -190. Weighted blends must stay between black and the inputs (up
// to inverse luma's rounding, about 2^-24 (1 + luma) relative).
TEST(CpuResolve, ToneWeightedBlendsStayBoundedForAnOutOfGamutHistory) {
  const vec3 history(440.0f, -440.0f, 440.0f), current(1000.0f, 0.0f, 1000.0f);
  ASSERT_LT(cpu::luma(history), -1.0f);
  for (auto w : {spec::ToneWeight::Karis, spec::ToneWeight::InverseLuma, spec::ToneWeight::Log})
    for (float alpha : {0.0f, 0.04f, 0.1f, 0.5f, 1.0f}) {
      const vec3 r = cpu::toneWeightedBlend(history, current, alpha, w);
      for (int k = 0; k < 3; ++k) {
        ASSERT_GE(r[k], 0.0f) << spec::enumToString(w) << " alpha " << alpha;
        ASSERT_LE(r[k], 1000.0f * (1.0f + 1e-4f)) << spec::enumToString(w) << " alpha " << alpha;
      }
    }
}

}  // namespace
}  // namespace taa
