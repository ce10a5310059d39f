// A YCoCg box is an axis-aligned box in a sheared space: its corners lie outside the RGB cube,
// so a rectified history can come back with negative components, and with shrink_chroma (the
// chroma extent centred on the current pixel) or a variance box even with luma <= -1. The
// tone-weighted blends must stay bounded there: 1 / (1 + luma) must not change sign or divide by
// zero and turn a dark pixel into a 65504 firefly that then lives on in the history.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/cpu_resolve.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

namespace cpu = test::cpu;

constexpr int kResolveToneWeightW = 24, kResolveToneWeightH = 16;

// Black, with isolated magenta fireflies of 1000: around each, the shrunk chroma box is centred
// on magenta (Cg = -500) while its luma range reaches down to black, so clamping the black
// history gives Y = 0 and Cg near -440: RGB (440, -440, 440), luma about -190.
test::SyntheticResolve magentaFireflies() {
  test::SyntheticResolve in;
  in.current = Image(kResolveToneWeightW, kResolveToneWeightH, 4, 0.0f);
  in.history = Image(kResolveToneWeightW, kResolveToneWeightH, 4, 0.0f);
  for (int y = 0; y < kResolveToneWeightH; ++y)
    for (int x = 0; x < kResolveToneWeightW; ++x) {
      in.current.at(x, y, 3) = in.history.at(x, y, 3) = 1.0f;
      if (x % 4 == 2 && y % 4 == 2) in.current.at(x, y, 0) = in.current.at(x, y, 2) = 1000.0f;
    }
  in.velocityPx = {0.0f, 0.0f};
  return in;
}

spec::CaseSpec shrinkChromaCase(spec::ToneWeight weighting) {
  spec::CaseSpec spec = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 24, "height": 16},
    "jitter": {"pattern": "none"},
    "script": {"frames": 2},
    "taa": {"mode": "full", "use_velocity": "all", "velocity_sampling": "pixel",
            "history_filter": "bilinear", "rectify": "clamp", "color_space": "ycocg",
            "shrink_chroma": true, "alpha": 0.1}
  })",
                                           "resolve_tone_weight");
  spec.taa.tonemap_weighting = weighting;
  return spec;
}

float maxChannel(const Image& img) {
  float m = 0.0f;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) m = std::max(m, img.at(x, y, c));
  return m;
}

TEST(ResolveToneWeighting, NegativeLumaHistoryDoesNotBecomeAFirefly) {
  const test::SyntheticResolve in = magentaFireflies();
  for (auto w : {spec::ToneWeight::None, spec::ToneWeight::Karis, spec::ToneWeight::InverseLuma,
                 spec::ToneWeight::Log}) {
    const spec::CaseSpec spec = shrinkChromaCase(w);
    // The scene is there: the rectified history next to a firefly has luma below -1.
    const cpu::Box box = [&] {
      cpu::Neighborhood n;
      for (int k = 0; k < 9; ++k) {
        const bool centre = k == 4;
        n.taps[k] = cpu::rgbToYCoCg(centre ? glm::vec3(1000.0f, 0.0f, 1000.0f) : glm::vec3(0.0f));
        n.valid[k] = true;
      }
      return cpu::neighborhoodBox(n, n.taps[4], spec.taa);
    }();
    ASSERT_LT(cpu::luma(cpu::yCoCgToRgb(cpu::clampToBox(glm::vec3(0.0f), box))), -1.0f);

    const test::GpuResolveResult gpu = test::gpuResolve(spec, in);
    const Image cpuOut = cpu::cpuResolve({gpu.current, gpu.history, gpu.velocityPx}, spec.taa);
    // Nothing brighter than the brightest input may come out.
    EXPECT_LE(maxChannel(gpu.output), 1000.0f) << spec::enumToString(w);
    EXPECT_LE(maxChannel(cpuOut), 1000.0f) << spec::enumToString(w);
  }
}

}  // namespace
}  // namespace taa

namespace taa {
namespace {

// A blend alone in c/(1+luma) space equals Karis' weighted average exactly; what tells
// inverse_luma and log apart is that their box and clipping run in the compressed domain.
TEST(ResolveToneWeighting, InverseLumaAndLogClipInTheirDomainSoTheyDifferFromKaris) {
  Image current(24, 16, 4, 1.0f), history(24, 16, 4, 1.0f);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 24; ++x)
      for (int c = 0; c < 3; ++c) {
        // HDR detail with occasional highlights in the current frame, a dull history.
        const uint32_t h = uint32_t(x * 73856093) ^ uint32_t(y * 19349663) ^ uint32_t(c * 83492791);
        current.at(x, y, c) = (h % 7 == 0) ? 40.0f : 0.05f + float(h % 97) / 40.0f;
        history.at(x, y, c) = 0.3f + float((h >> 8) % 13) / 10.0f;
      }
  const test::cpu::CpuResolveInputs in{current, history, glm::vec2(0.25f, -0.5f)};
  spec::TaaSpec taa;
  taa.rectify = spec::Rectify::Clip;
  taa.color_space = spec::ColorSpace::Rgb;
  taa.history_filter = spec::HistoryFilter::Bilinear;
  taa.velocity_sampling = spec::VelocitySampling::Pixel;
  auto resolveWith = [&](spec::ToneWeight w) {
    taa.tonemap_weighting = w;
    return test::cpu::cpuResolve(in, taa);
  };
  const Image karis = resolveWith(spec::ToneWeight::Karis);
  const Image inverse = resolveWith(spec::ToneWeight::InverseLuma);
  const Image logDomain = resolveWith(spec::ToneWeight::Log);
  auto shareDiffering = [](const Image& a, const Image& b) {
    int n = 0;
    for (size_t i = 0; i < a.data.size(); ++i) n += std::fabs(a.data[i] - b.data[i]) > 1e-3f * (1.0f + std::fabs(a.data[i]));
    return double(n) / double(a.data.size());
  };
  EXPECT_GT(shareDiffering(karis, inverse), 0.05);
  EXPECT_GT(shareDiffering(karis, logDomain), 0.05);
  EXPECT_GT(shareDiffering(inverse, logDomain), 0.05);
}

}  // namespace
}  // namespace taa
