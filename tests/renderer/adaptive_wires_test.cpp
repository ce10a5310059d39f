// The seed's Figure 3: sub-pixel wires under a moving camera fade with TAA (history
// clipping removes what this frame's samples missed) and stay with adaptive ray
// tracing. Measured against the supersampled reference on cases/adaptive_wires.json:
// the wires' coverage is the luma they take away from what lies behind them (the
// reference of the same scene with the wires removed), summed around the wires.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "api/renderer.h"
#include "case/case_loader.h"
#include "scene/build_scene.h"
#include "support/gpu.h"

namespace taa {
namespace {

const std::vector<int> kMeasured = {12, 17, 23};

spec::CaseSpec wiresCase(spec::TaaMode mode) {
  auto spec = cases::loadCase(std::string(TAA_SOURCE_DIR) + "/cases/adaptive_wires.json").spec;
  spec.taa.mode = mode;
  spec.reference.samples = 16;
  return spec;
}

// Output images at kMeasured, and with `reference` the reference images too.
struct WireImages {
  std::vector<Image> color, reference;
};
WireImages render(const spec::CaseSpec& spec, const scene::Scene& scene, bool reference) {
  RenderOptions o;
  if (reference) o.captures |= {Capture::Reference};
  Renderer renderer(test::gpu(), spec, scene, o);
  WireImages out;
  for (int f = 0; f < spec.script.frames; ++f) {
    const bool wanted = std::find(kMeasured.begin(), kMeasured.end(), f) != kMeasured.end();
    FrameRecord r = renderer.renderFrame(f, wanted);
    if (!wanted) continue;
    out.color.push_back(std::move(r.color));
    if (reference) out.reference.push_back(std::move(r.reference));
  }
  return out;
}

float luma(const Image& img, int x, int y) {
  float l = 0.0f;
  const float w[3] = {0.2126f, 0.7152f, 0.0722f};
  for (int c = 0; c < 3; ++c) l += w[c] * img.at(x, y, c) / (1.0f + img.at(x, y, c));
  return l;
}

struct Coverage {
  double ratio = 0.0;  // coverage / the reference's coverage
  double error = 0.0;  // sum |luma - reference luma| / the reference's coverage
};

Coverage measure(const std::vector<Image>& images, const std::vector<Image>& ref,
                 const std::vector<Image>& bare) {
  double covered = 0.0, refCovered = 0.0, error = 0.0;
  for (size_t i = 0; i < images.size(); ++i) {
    const Image& r = ref[i];
    // Around the wires: within 2 pixels of where the reference differs from the bare scene.
    std::vector<bool> wire(r.pixelCount(), false);
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x)
        if (std::abs(luma(r, x, y) - luma(bare[i], x, y)) > 1e-3f)
          for (int dy = -2; dy <= 2; ++dy)
            for (int dx = -2; dx <= 2; ++dx) {
              const int u = x + dx, v = y + dy;
              if (u >= 0 && v >= 0 && u < r.width && v < r.height)
                wire[size_t(v) * size_t(r.width) + size_t(u)] = true;
            }
    for (int y = 0; y < r.height; ++y)
      for (int x = 0; x < r.width; ++x) {
        if (!wire[size_t(y) * size_t(r.width) + size_t(x)]) continue;
        const float background = luma(bare[i], x, y);
        covered += background - luma(images[i], x, y);
        refCovered += background - luma(r, x, y);
        error += std::abs(luma(images[i], x, y) - luma(r, x, y));
      }
  }
  return {covered / refCovered, error / refCovered};
}

TEST(AdaptiveWires, WiresKeptWithAdaptiveAndVanishingWithout) {
  const auto adaptiveSpec = wiresCase(spec::TaaMode::Adaptive);
  const auto fullSpec = wiresCase(spec::TaaMode::Full);
  const scene::Scene scene = scene::buildScene(adaptiveSpec);
  scene::Scene bare = scene;
  for (auto& mesh : bare.meshes)
    if (mesh.name == "wires")
      for (auto& p : mesh.primitives) p.indexCount = 0;

  // The full resolve's run gives the reference too: a capture never changes the output.
  const WireImages full = render(fullSpec, scene, true);
  const auto background = render(fullSpec, bare, true).reference;
  const Coverage adaptive = measure(render(adaptiveSpec, scene, false).color, full.reference, background);
  const Coverage fullTaa = measure(full.color, full.reference, background);
  std::printf(
      "[ wire coverage vs reference ] adaptive %.3f (error %.3f), full TAA %.3f (error %.3f)\n",
      adaptive.ratio, adaptive.error, fullTaa.ratio, fullTaa.error);
  // Without tracing most of the wires' coverage is gone; with it they keep most of it.
  EXPECT_LT(fullTaa.ratio, 0.6);
  EXPECT_GT(adaptive.ratio, 0.75);
  EXPECT_LT(adaptive.ratio, 1.25);
  EXPECT_LT(std::abs(1.0 - adaptive.ratio), 0.5 * std::abs(1.0 - fullTaa.ratio));
  EXPECT_LT(adaptive.error, fullTaa.error);
}

}  // namespace
}  // namespace taa
