// glTF sidedness on every path that draws (cases/scenes/culling.gltf): a single-sided quad
// turned away from the camera is culled, so what lies behind it shows; a double-sided one
// turned away is drawn with its flipped normal, as bright as its twin facing the camera.
// The shadow casters and the adaptive tracer cull alike. Before issue 25 every draw had cull
// mode none: the turned-away red quad showed, and cast its shadow.
#include <gtest/gtest.h>

#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

// The quads' centres (y 0.9, z 0): single-sided facing, turned away; double-sided facing,
// turned away.
constexpr float kQuadX[4] = {-1.8f, -0.6f, 0.6f, 1.8f};
constexpr float kQuadY = 0.9f;
const char* const kQuadName[4] = {"single-sided facing", "single-sided turned away",
                                  "double-sided facing", "double-sided turned away"};

std::string cullingScene(const std::string& path, bool shadows) {
  return R"("scene": {"gltf": "scenes/culling.gltf"},
    "camera": {"position": [0, 1.3, 3.6], "target": [0, 0.8, 0]},
    "render": {"path": ")" + path + R"("}, "reference": {"samples": 4},
    "lighting": {"direction": [0.25, -1.0, -0.6], "specular": 0, "shadows": )" +
         (shadows ? "true" : "false") + "}";
}

bool reddish(const Image& im, test::Pixel p) {
  return test::meanAround(im, p, 0) > 2.0f * test::meanAround(im, p, 1);
}

void expectSidedness(const Image& im, const spec::CaseSpec& spec, const std::string& what) {
  test::Pixel at[4];
  for (int q = 0; q < 4; ++q) at[q] = test::pixelOf(spec, {kQuadX[q], kQuadY, 0.0f});
  EXPECT_TRUE(reddish(im, at[0])) << what << ": the single-sided quad facing the camera shows";
  EXPECT_FALSE(reddish(im, at[1])) << what << ": the turned-away single-sided quad is culled";
  EXPECT_GT(test::meanAround(im, at[2], 1), 2.0f * test::meanAround(im, at[2], 0)) << what;
  for (int c = 0; c < 3; ++c) {
    const float facing = test::meanAround(im, at[2], c);
    EXPECT_NEAR(test::meanAround(im, at[3], c), facing, 0.01f * facing + 1e-4f)
        << what << ": the turned-away double-sided quad is lit by its flipped normal, channel "
        << c;
  }
}

TEST(Culling, SingleSidedBackFacesAreCulledOnTheForwardDeferredAndReferencePaths) {
  for (const char* path : {"forward", "deferred"}) {
    const auto spec = test::stillCase(cullingScene(path, false), std::string("culling_") + path);
    RenderOptions o;
    o.captures |= {Capture::Reference};
    const auto records = test::renderCaseWith(spec, o);
    expectSidedness(records[0].color, spec, path);
    expectSidedness(test::capturedImage(records[0], Capture::Reference), spec, std::string(path) + " reference");
  }
}

TEST(Culling, TheTracerPassesThroughWhatTheRasterCulls) {
  const auto spec = test::stillCase(cullingScene("forward", false), "culling_traced");
  const test::TracedAndRaster r = test::traceEveryPixel(cullingScene("forward", false));
  for (int q = 0; q < 4; ++q) {
    const test::Pixel p = test::pixelOf(spec, {kQuadX[q], kQuadY, 0.0f});
    test::expectTracedMatchesRaster(r, p.x, p.y, kQuadName[q]);
  }
  EXPECT_FALSE(reddish(r.traced, test::pixelOf(spec, {kQuadX[1], kQuadY, 0.0f})));
}

TEST(Culling, ShadowCastersCullAsTheRasterDoes) {
  // Each quad's centre casts onto the floor at centre + 0.9 / 1.0 * (0.25, -1, -0.6).
  const auto on = test::stillCase(cullingScene("forward", true), "culling_shadows_on");
  const auto off = test::stillCase(cullingScene("forward", false), "culling_shadows_off");
  const Image lit = test::renderStill(on), unshadowed = test::renderStill(off);
  for (int q = 0; q < 4; ++q) {
    const test::Pixel p = test::pixelOf(on, {kQuadX[q] + 0.225f, 0.0f, -0.54f});
    const float ratio = test::meanAround(lit, p, 1) / test::meanAround(unshadowed, p, 1);
    if (q == 1)
      EXPECT_GT(ratio, 0.97f) << kQuadName[q] << " casts no shadow: its front faces away";
    else
      EXPECT_LT(ratio, 0.8f) << kQuadName[q] << " casts a shadow";
  }
}

}  // namespace
}  // namespace taa
