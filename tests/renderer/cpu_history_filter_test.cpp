// Properties of the history filters (shaders/taa/history_filter.glsl via support/cpu_resolve):
// what a cubic filter must reproduce exactly, what it must not, and how far the 5-tap
// Catmull-Rom approximation may stray from the exact 16-tap one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>

#include "support/cpu_resolve.h"
#include "support/noise.h"

namespace taa {
namespace {

using glm::vec2;
using glm::vec3;
using test::hashUnit;
namespace cpu = test::cpu;

constexpr int kCpuHistoryFilterW = 40, kCpuHistoryFilterH = 30;

using Filter = std::function<vec3(const Image&, vec2)>;
struct Named {
  const char* name;
  Filter filter;
};
const Named kBilinear{"bilinear", cpu::bilinear};
const Named kBSpline{"bspline", cpu::historyBSpline};
const Named kCatmullRom9{"catmull_rom_9", cpu::historyCatmullRom9};
const Named kCatmullRom5{"catmull_rom_5", cpu::historyCatmullRom5};
const Named kCatmullRom16{"catmull_rom_16", cpu::historyCatmullRom16};

Image fill(const std::function<vec3(int, int)>& f) {
  Image img(kCpuHistoryFilterW, kCpuHistoryFilterH, 4, 1.0f);
  for (int y = 0; y < kCpuHistoryFilterH; ++y)
    for (int x = 0; x < kCpuHistoryFilterW; ++x)
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = f(x, y)[c];
  return img;
}

vec3 ramp(float x, float y) {
  return {0.5f + 0.25f * x, 2.0f - 0.125f * y, 0.0625f * (x + y)};
}

// A position whose 4x4 footprint lies inside the image (no edge clamping), as texel
// coordinates p (texel centres at integers) and as the uv the filters take.
vec2 interiorTexelPos(int i) {
  return {1.0f + hashUnit(20, i, 0) * float(kCpuHistoryFilterW - 4), 1.0f + hashUnit(20, i, 1) * float(kCpuHistoryFilterH - 4)};
}
vec2 toUv(vec2 p) {
  return (p + 0.5f) / vec2(kCpuHistoryFilterW, kCpuHistoryFilterH);
}

TEST(CpuResolve, FiltersReproduceLinearRampsExactly) {
  const Image img = fill([](int x, int y) { return ramp(float(x), float(y)); });
  // Catmull-Rom and the cubic B-spline both reproduce polynomials of degree 1; the 9-tap form
  // must keep that although it folds the middle texels into one bilinear tap.
  for (const Named& f : {kBilinear, kBSpline, kCatmullRom9, kCatmullRom16}) {
    double worst = 0.0;
    for (int i = 0; i < 2000; ++i) {
      const vec2 p = interiorTexelPos(i);
      const vec3 got = f.filter(img, toUv(p)), want = ramp(p.x, p.y);
      for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(got[c] - want[c])));
    }
    // The values reach 10; float rounding of uv and weights leaves a few 1e-6.
    EXPECT_LT(worst, 2e-5) << f.name;
  }
}

TEST(CpuResolve, CatmullRomInterpolatesTexelCentresExactly) {
  const Image img = fill([](int x, int y) {
    return 8.0f * vec3(hashUnit(21, x, y, 0), hashUnit(21, x, y, 1), hashUnit(21, x, y, 2));
  });
  // The 16-tap form only sees (x + 0.5) / w rounded; the 9- and 5-tap forms also round their
  // tap positions to uv and back (a few ulps of 40 texels, 5e-6 px, times values up to 8).
  for (const Named& f : {kCatmullRom9, kCatmullRom5, kCatmullRom16}) {
    const double bound = f.name == kCatmullRom16.name ? 1e-5 : 5e-5;
    double worst = 0.0;
    for (int y = 0; y < kCpuHistoryFilterH; ++y)
      for (int x = 0; x < kCpuHistoryFilterW; ++x) {
        const vec3 got = f.filter(img, toUv(vec2(x, y)));
        for (int c = 0; c < 3; ++c)
          worst = std::max(worst, double(std::abs(got[c] - img.at(x, y, c))));
      }
    EXPECT_LT(worst, bound) << f.name;
  }
}

TEST(CpuResolve, BSplineSmoothsTexelCentresButReproducesConstants) {
  const Image noise = fill([](int x, int y) {
    return 8.0f * vec3(hashUnit(22, x, y, 0), hashUnit(22, x, y, 1), hashUnit(22, x, y, 2));
  });
  int smoothed = 0;
  for (int y = 1; y < kCpuHistoryFilterH - 1; ++y)
    for (int x = 1; x < kCpuHistoryFilterW - 1; ++x) {
      const vec3 got = cpu::historyBSpline(noise, toUv(vec2(x, y)));
      for (int c = 0; c < 3; ++c) {
        // At a texel centre the cubic B-spline weighs the 3x3 texels by (1, 4, 1) / 6 per axis.
        double want = 0.0;
        for (int j = -1; j <= 1; ++j)
          for (int i = -1; i <= 1; ++i)
            want += (i == 0 ? 4.0 : 1.0) * (j == 0 ? 4.0 : 1.0) / 36.0 * noise.at(x + i, y + j, c);
        ASSERT_NEAR(got[c], want, 1e-5);
        smoothed += std::abs(got[c] - noise.at(x, y, c)) > 0.05f;
      }
    }
  EXPECT_GT(smoothed, (kCpuHistoryFilterW - 2) * (kCpuHistoryFilterH - 2) * 3 * 9 / 10);  // it does not interpolate
  // Constants pass every filter unchanged, edges (clamped texels) included.
  const Image flat = fill([](int, int) { return vec3(3.7f, 0.25f, 1e3f); });
  for (const Named& f : {kBilinear, kBSpline, kCatmullRom9, kCatmullRom5, kCatmullRom16})
    for (int i = 0; i < 500; ++i) {
      const vec2 uv(hashUnit(23, i, 0), hashUnit(23, i, 1));
      const vec3 got = f.filter(flat, uv);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(got[c], flat.at(0, 0, c), 2e-6f * flat.at(0, 0, c)) << f.name;
    }
}

// On a band-limited signal (a 16-pixel wavelength, amplitude 2) the 5-tap approximation may
// differ from the exact 16-tap Catmull-Rom by at most 1% of the amplitude. Dropping the corner
// taps costs up to about 0.007 px of position on a ramp (worst near a quarter texel), i.e.
// 0.007 * 2 * 2 pi / 16 = 0.0055 here, plus a curvature term of the same order.
TEST(CpuResolve, CatmullRom5StaysWithinOnePercentOfCatmullRom16OnSmoothData) {
  const float k = 2.0f * std::numbers::pi_v<float> / 16.0f;
  const Image smooth = fill([k](int x, int y) {
    const float v = 4.0f + 2.0f * std::sin(k * x) * std::cos(k * y);
    return vec3(v, 8.0f - v, 0.5f * v);
  });
  double worst = 0.0, worstNoise = 0.0;
  const Image noise = fill([](int x, int y) { return vec3(8.0f * hashUnit(24, x, y)); });
  for (int i = 0; i < 4000; ++i) {
    const vec2 uv = toUv(interiorTexelPos(i));
    const vec3 d = cpu::historyCatmullRom5(smooth, uv) - cpu::historyCatmullRom16(smooth, uv);
    worst = std::max({worst, double(std::abs(d.x)), double(std::abs(d.y)), double(std::abs(d.z))});
    worstNoise = std::max(worstNoise, double(std::abs(cpu::historyCatmullRom5(noise, uv).x -
                                                      cpu::historyCatmullRom16(noise, uv).x)));
  }
  std::printf("[ filters   ] |cr5 - cr16| max %.4g on smooth data, %.4g on noise\n", worst,
              worstNoise);
  EXPECT_LT(worst, 0.02);
  // It is an approximation all the same: on noise in [0, 8) the dropped corners show.
  EXPECT_GT(worstNoise, 0.04);
}

}  // namespace
}  // namespace taa
