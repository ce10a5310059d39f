// A YCoCg box is an axis-aligned box in a sheared space: its corners lie outside the RGB cube,
// so a rectified history can come back with negative components, and with shrink_chroma (the
// chroma extent centred on the current pixel) or a variance box even with luma <= -1. The
// tone-weighted blends must stay bounded there: 1 / (1 + luma) must not change sign or divide by
// zero and turn a dark pixel into a 65504 firefly that then lives on in the history.
#include <gtest/gtest.h>

#include <algorithm>

#include "support/cpu_resolve.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

namespace cpu = test::cpu;

constexpr int kW = 24, kH = 16;

// Black, with isolated magenta fireflies of 1000: around each, the shrunk chroma box is centred
// on magenta (Cg = -500) while its luma range reaches down to black, so clamping the black
// history gives Y = 0 and Cg near -440: RGB (440, -440, 440), luma about -190.
test::SyntheticResolve magentaFireflies() {
  test::SyntheticResolve in;
  in.current = Image(kW, kH, 4, 0.0f);
  in.history = Image(kW, kH, 4, 0.0f);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
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
