// The GPU resolve (TaaResolvePass on lavapipe) agrees pixel by pixel with the CPU mirror of its
// formulas (support/cpu_resolve) for every colour technique, on deterministic HDR noise. Each
// test also checks that the comparison can tell the technique apart: the CPU result with the
// technique switched off (or changed) must disagree with the GPU on many pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

#include "core/image_io.h"
#include "support/cpu_resolve.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"
#include "support/noise.h"

namespace taa {
namespace {

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// Every technique runs twice, once per history format. Tolerances per channel:
// - RGBA32F: |gpu - cpu| <= kFloatTol * M, M = the largest input channel value within 3 pixels
//   (current and history; at least 1). The mirror evaluates the same float formulas; what is
//   left is evaluation order, fused multiply-adds and lavapipe's exp / log / sqrt / division,
//   a few float ulps of the values being combined, which near a 1e3 firefly are its ulps. The
//   inverse-luma blend adds kPoleTol * (1 + luma) * |cpu|: its inverse c / (1 - luma) loses
//   that factor to the cancellation in 1 - luma for bright colours.
// - RGBA16F: the same plus one half ulp of |cpu|, with cpu rounded to half (round to nearest
//   even) as the resolve rounds its history before the store; the few float ulps between the
//   two evaluations can still tip a value across a rounding midpoint.
constexpr double kFloatTol = 1e-6;
constexpr double kPoleTol = 4.0 / (1 << 24);

// HDR noise in [0, 8) per channel; one pixel in about 24 is a firefly near 1e3 (the whole pixel
// scaled, so its hue stays ordinary).
Image hdrNoise(uint32_t seed) {
  Image img(kWidth, kHeight, 4, 1.0f);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const float scale = test::hashUnit(seed, x, y, 7) < 1.0f / 24.0f ? 125.0f : 1.0f;
      for (int c = 0; c < 3; ++c) img.at(x, y, c) = 8.0f * test::hashUnit(seed, x, y, c) * scale;
    }
  return img;
}

double halfUlp(double v) {
  int e = 0;
  std::frexp(std::abs(v), &e);  // |v| = m * 2^e, m in [0.5, 1)
  return std::ldexp(1.0, std::max(e - 11, -24));
}

float stored(float v, bool half) {
  return half ? halfBitsToFloat(floatToHalfBits(v)) : v;
}

// M of the tolerance: the input scale within reach of each pixel's 3x3 box and history taps.
Image inputScale(const Image& current, const Image& history) {
  Image m(current.width, current.height, 1, 1.0f);
  for (int y = 0; y < m.height; ++y)
    for (int x = 0; x < m.width; ++x)
      for (int j = std::max(y - 3, 0); j <= std::min(y + 3, m.height - 1); ++j)
        for (int i = std::max(x - 3, 0); i <= std::min(x + 3, m.width - 1); ++i)
          for (int c = 0; c < 3; ++c)
            m.at(x, y) = std::max({m.at(x, y), current.at(i, j, c), history.at(i, j, c)});
  return m;
}

struct ResolverAgreement {
  double maxRelative = 0.0;     // max |gpu - cpu| / max(|cpu|, 1e-3)
  double maxOfScale = 0.0;      // max |gpu - cpu| / M
  int maxHalfUlps = 0;          // RGBA16F: the largest distance in half ulps
  double maxOfTolerance = 0.0;  // max |gpu - cpu| / tolerance: <= 1 passes
  int outside = 0;              // channels beyond tolerance
  int differing = 0;            // channels not bit-identical
  int channels = 0;

  void add(const ResolverAgreement& o) {
    maxRelative = std::max(maxRelative, o.maxRelative);
    maxOfScale = std::max(maxOfScale, o.maxOfScale);
    maxHalfUlps = std::max(maxHalfUlps, o.maxHalfUlps);
    maxOfTolerance = std::max(maxOfTolerance, o.maxOfTolerance);
    outside += o.outside;
    differing += o.differing;
    channels += o.channels;
  }
};

struct Comparison {
  const Image& scale;  // inputScale of the frame
  bool half;
  bool inverseLuma;
  bool quiet = false;  // for the control, which is meant to disagree
};

// `cpuOut` is the mirror's float result, rounded here as the history format stores it.
ResolverAgreement compare(const Image& gpuOut, const Image& cpuOut, const Comparison& k) {
  ResolverAgreement a;
  for (int y = 0; y < cpuOut.height; ++y)
    for (int x = 0; x < cpuOut.width; ++x) {
      const double lumaCpu = luminance(cpuOut, x, y);
      for (int c = 0; c < 3; ++c) {
        const float cpu = stored(cpuOut.at(x, y, c), k.half), gpu = gpuOut.at(x, y, c);
        const double d = std::abs(double(gpu) - double(cpu)), m = k.scale.at(x, y);
        double tol = kFloatTol * m;
        if (k.inverseLuma) tol += kPoleTol * (1.0 + std::max(lumaCpu, 0.0)) * std::abs(cpu);
        if (k.half) tol += halfUlp(cpu);
        a.maxRelative = std::max(a.maxRelative, d / std::max(std::abs(double(cpu)), 1e-3));
        a.maxOfScale = std::max(a.maxOfScale, d / m);
        if (k.half)
          a.maxHalfUlps = std::max(a.maxHalfUlps,
                                   std::abs(int(floatToHalfBits(gpu)) - int(floatToHalfBits(cpu))));
        a.maxOfTolerance = std::max(a.maxOfTolerance, d / tol);
        a.differing += gpu != cpu;
        ++a.channels;
        if (d <= tol) continue;
        if (!k.quiet && a.outside < 5)
          ADD_FAILURE() << (k.half ? "rgba16f" : "rgba32f") << " pixel " << x << "," << y
                        << " channel " << c << ": gpu " << gpu << " cpu " << cpu;
        ++a.outside;
      }
    }
  return a;
}

using Mutate = std::function<void(spec::TaaSpec&)>;

// Velocity reprojection from the pixel's own (constant) velocity, offscreen rejection, the
// bilinear filter, an RGB clamp and plain blending: each test changes what it is about.
spec::CaseSpec baseCase() {
  return test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 64, "height": 48},
    "jitter": {"pattern": "none"},
    "script": {"frames": 2},
    "taa": {"mode": "full", "use_velocity": "all", "velocity_sampling": "pixel",
            "reject_offscreen": true, "history_filter": "bilinear", "rectify": "clamp",
            "color_space": "rgb", "alpha": 0.1}
  })",
                            "resolve_agreement");
}

// Sub-pixel velocities exactly representable in RG16F. With one constant velocity every pixel
// samples the history at the same sub-texel phase, so filters are checked at several.
const std::vector<glm::vec2> kOneVelocity = {{0.37109375f, -0.2890625f}};
const std::vector<glm::vec2> kPhases = {
    {0.37109375f, -0.2890625f}, {-0.8125f, 0.0625f}, {0.0f, 0.5f}, {0.96875f, -0.96875f}};

void checkAgreement(const Mutate& technique, const Mutate& control,
                    const std::vector<glm::vec2>& velocities = kOneVelocity) {
  const auto* info = testing::UnitTest::GetInstance()->current_test_info();
  for (bool half : {false, true}) {
    spec::CaseSpec spec = baseCase();
    technique(spec.taa);
    spec.taa.history_format = half ? spec::HistoryFormat::Rgba16f : spec::HistoryFormat::Rgba32f;
    spec::TaaSpec controlSpec = spec.taa;
    control(controlSpec);
    ResolverAgreement total, controlTotal;
    for (size_t v = 0; v < velocities.size(); ++v) {
      test::SyntheticResolve in;
      in.current = hdrNoise(0x1234u + uint32_t(v));
      in.history = hdrNoise(0xabcdu + uint32_t(v));
      in.velocityPx = velocities[v];
      const test::GpuResolveResult gpu = test::gpuResolve(spec, in);
      const test::cpu::CpuResolveInputs cpuIn{gpu.current, gpu.history, gpu.velocityPx};
      const Image scale = inputScale(gpu.current, gpu.history);
      const bool inverseLuma = spec.taa.tonemap_weighting == spec::ToneWeight::InverseLuma;
      total.add(
          compare(gpu.output, test::cpu::cpuResolve(cpuIn, spec.taa), {scale, half, inverseLuma}));
      controlTotal.add(compare(gpu.output, test::cpu::cpuResolve(cpuIn, controlSpec),
                               {scale, half, inverseLuma, true}));
    }
    std::printf(
        "[ agreement ] %-24s %s max rel %.2g, max/M %.2g, %d half ulps, max/tol %.2f, %.0f%% "
        "not bit-identical; control outside tol on %.0f%%\n",
        info->name(), half ? "rgba16f" : "rgba32f", total.maxRelative, total.maxOfScale,
        total.maxHalfUlps, total.maxOfTolerance, 100.0 * total.differing / total.channels,
        100.0 * controlTotal.outside / controlTotal.channels);
    testing::Test::RecordProperty(half ? "max_relative_rgba16f" : "max_relative_rgba32f",
                                  std::to_string(total.maxRelative));
    EXPECT_EQ(total.outside, 0) << (half ? "rgba16f" : "rgba32f");
    EXPECT_GT(controlTotal.outside, controlTotal.channels / 100)
        << "the comparison cannot tell the technique apart";
  }
}

using spec::ColorSpace;
using spec::HistoryFilter;
using spec::Rectify;
using spec::ToneWeight;

const Mutate kRgb = [](spec::TaaSpec& t) { t.color_space = ColorSpace::Rgb; };
const Mutate kNoRectify = [](spec::TaaSpec& t) { t.rectify = Rectify::None; };
const Mutate kBilinearFilter = [](spec::TaaSpec& t) { t.history_filter = HistoryFilter::Bilinear; };
const Mutate kNoToneWeight = [](spec::TaaSpec& t) { t.tonemap_weighting = ToneWeight::None; };

TEST(ResolveAgreement, ClampRgb) {
  checkAgreement([](spec::TaaSpec&) {}, kNoRectify);
}

TEST(ResolveAgreement, ClampYCoCg) {
  checkAgreement([](spec::TaaSpec& t) { t.color_space = ColorSpace::YCoCg; }, kRgb);
}

TEST(ResolveAgreement, ClipRgb) {
  checkAgreement([](spec::TaaSpec& t) { t.rectify = Rectify::Clip; },
                 [](spec::TaaSpec& t) { t.rectify = Rectify::Clamp; });
}

TEST(ResolveAgreement, ClipYCoCg) {
  checkAgreement(
      [](spec::TaaSpec& t) {
        t.rectify = Rectify::Clip;
        t.color_space = ColorSpace::YCoCg;
      },
      kRgb);
}

TEST(ResolveAgreement, VarianceClipGamma1) {
  checkAgreement(
      [](spec::TaaSpec& t) {
        t.rectify = Rectify::Clip;
        t.color_space = ColorSpace::YCoCg;
        t.variance_clip = true;
        t.variance_gamma = 1.0f;
      },
      [](spec::TaaSpec& t) { t.variance_clip = false; });
}

TEST(ResolveAgreement, VarianceClipGamma075) {
  checkAgreement(
      [](spec::TaaSpec& t) {
        t.rectify = Rectify::Clip;
        t.variance_clip = true;
        t.variance_gamma = 0.75f;
      },
      [](spec::TaaSpec& t) { t.variance_gamma = 1.0f; });
}

TEST(ResolveAgreement, ShapedNeighborhood) {
  checkAgreement([](spec::TaaSpec& t) { t.shaped_neighborhood = true; },
                 [](spec::TaaSpec& t) { t.shaped_neighborhood = false; });
}

TEST(ResolveAgreement, ShrinkChroma) {
  checkAgreement(
      [](spec::TaaSpec& t) {
        t.rectify = Rectify::Clip;
        t.color_space = ColorSpace::YCoCg;
        t.shrink_chroma = true;
      },
      [](spec::TaaSpec& t) { t.shrink_chroma = false; });
}

TEST(ResolveAgreement, Bilinear) {
  checkAgreement([](spec::TaaSpec&) {},
                 [](spec::TaaSpec& t) { t.history_filter = HistoryFilter::CatmullRom16; }, kPhases);
}

TEST(ResolveAgreement, BSpline) {
  checkAgreement([](spec::TaaSpec& t) { t.history_filter = HistoryFilter::BSpline; }, kBilinearFilter,
                 kPhases);
}

TEST(ResolveAgreement, CatmullRom9) {
  checkAgreement([](spec::TaaSpec& t) { t.history_filter = HistoryFilter::CatmullRom9; }, kBilinearFilter,
                 kPhases);
}

TEST(ResolveAgreement, CatmullRom5) {
  checkAgreement([](spec::TaaSpec& t) { t.history_filter = HistoryFilter::CatmullRom5; },
                 [](spec::TaaSpec& t) { t.history_filter = HistoryFilter::CatmullRom9; }, kPhases);
}

TEST(ResolveAgreement, CatmullRom16) {
  checkAgreement([](spec::TaaSpec& t) { t.history_filter = HistoryFilter::CatmullRom16; },
                 kBilinearFilter, kPhases);
}

TEST(ResolveAgreement, KarisToneWeighting) {
  checkAgreement([](spec::TaaSpec& t) { t.tonemap_weighting = ToneWeight::Karis; }, kNoToneWeight);
}

TEST(ResolveAgreement, InverseLumaToneWeighting) {
  checkAgreement([](spec::TaaSpec& t) { t.tonemap_weighting = ToneWeight::InverseLuma; },
                 kNoToneWeight);
}

TEST(ResolveAgreement, LogToneWeighting) {
  checkAgreement([](spec::TaaSpec& t) { t.tonemap_weighting = ToneWeight::Log; }, kNoToneWeight);
}

TEST(ResolveAgreement, LottesLumaWeighting) {
  checkAgreement([](spec::TaaSpec& t) { t.luma_weight = true; },
                 [](spec::TaaSpec& t) { t.luma_weight = false; });
}

TEST(ResolveAgreement, ReduceBlendNearClamp) {
  checkAgreement([](spec::TaaSpec& t) { t.reduce_blend_near_clamp = true; },
                 [](spec::TaaSpec& t) { t.reduce_blend_near_clamp = false; });
}

// Everything at once, as the project's default case runs it (YCoCg clip, 5-tap Catmull-Rom),
// plus variance clipping, luma weighting and Karis weighting, at several phases.
TEST(ResolveAgreement, CombinedDefaults) {
  checkAgreement(
      [](spec::TaaSpec& t) {
        t = spec::TaaSpec{};
        t.velocity_sampling = spec::VelocitySampling::Pixel;
        t.variance_clip = true;
        t.luma_weight = true;
        t.tonemap_weighting = ToneWeight::Karis;
      },
      kNoRectify, kPhases);
}

}  // namespace
}  // namespace taa
