// A material's maps on their UV sets, and unlit materials, on the forward, deferred and
// traced paths. cases/scenes/uv1_emissive.gltf gives three quads a TEXCOORD_1 that is
// TEXCOORD_0 transposed, so a 2x1 texture on the second set splits a quad top and bottom
// (on the first set it would split it left and right): an emissive texture, an occlusion
// texture and a base-colour texture. cases/scenes/unlit.gltf sets a lit and a
// KHR_materials_unlit quad of one texture side by side under a bar's shadow. Before issue 25
// the emissive texture was dropped (no emission at all), occlusion was ignored, TEXCOORD_1
// was refused and the unlit quad was lit: each expectation below then fails.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/textures.h"
#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

const char* kUv1Members = R"("scene": {"gltf": "scenes/uv1_emissive.gltf"},
    "camera": {"position": [0, 1.1, 3.2], "target": [0, 0.85, 0]},
    "lighting": {"ambient": [0.3, 0.3, 0.3], "specular": 0})";

// A quad's quarter centres: top and bottom halves (y 1.15, 0.65), left and right (x -+0.25).
struct Quarters {
  test::Pixel topLeft, topRight, bottomLeft, bottomRight;
};
Quarters quarters(const spec::CaseSpec& spec, float x, float y) {
  return {test::pixelOf(spec, {x - 0.25f, y + 0.25f, 0.0f}),
          test::pixelOf(spec, {x + 0.25f, y + 0.25f, 0.0f}),
          test::pixelOf(spec, {x - 0.25f, y - 0.25f, 0.0f}),
          test::pixelOf(spec, {x + 0.25f, y - 0.25f, 0.0f})};
}

float value(const Image& im, test::Pixel p, int c) { return test::meanAround(im, p, c); }

// Left and right agree: the split follows TEXCOORD_1 (top, bottom), not TEXCOORD_0.
void expectSplitTopAndBottom(const Image& im, const Quarters& q, const std::string& what) {
  for (int c = 0; c < 3; ++c) {
    const float top = value(im, q.topLeft, c), bottom = value(im, q.bottomLeft, c);
    EXPECT_NEAR(value(im, q.topRight, c), top, 0.02f * top + 1e-3f) << what << " channel " << c;
    EXPECT_NEAR(value(im, q.bottomRight, c), bottom, 0.02f * bottom + 1e-3f)
        << what << " channel " << c;
  }
}

void expectUv1Maps(const Image& im, const spec::CaseSpec& spec, const std::string& path) {
  const Quarters emissive = quarters(spec, -1.2f, 0.9f), occlusion = quarters(spec, 0.0f, 0.9f),
                 base = quarters(spec, 1.2f, 0.9f);
  // Emission (1, 0, 0) from the texture's red texel on the top half, none below.
  EXPECT_GT(value(im, emissive.topLeft, 0), 1.0f) << path << ": the emissive texture glows";
  EXPECT_LT(value(im, emissive.topLeft, 1), 0.3f) << path;
  EXPECT_LT(value(im, emissive.bottomLeft, 0), 0.5f) << path << ": its black texel adds nothing";
  expectSplitTopAndBottom(im, emissive, path + " emissive");
  // Occlusion 1 on the top half, 0 below: the ambient 0.3 reaches the top alone.
  for (int c = 0; c < 3; ++c)
    EXPECT_GT(value(im, occlusion.topLeft, c) - value(im, occlusion.bottomLeft, c), 0.15f)
        << path << ": occlusion darkens the ambient term, channel " << c;
  expectSplitTopAndBottom(im, occlusion, path + " occlusion");
  // Base colour white on the top half, blue below.
  EXPECT_GT(value(im, base.bottomLeft, 2), 2.0f * value(im, base.bottomLeft, 0)) << path;
  EXPECT_LT(value(im, base.topLeft, 2), 1.2f * value(im, base.topLeft, 0)) << path << ": white";
  expectSplitTopAndBottom(im, base, path + " base colour");
}

TEST(MaterialMaps, TexCoord1CarriesEmissiveOcclusionAndBaseColourOnBothPaths) {
  for (const char* path : {"forward", "deferred"}) {
    const auto spec = test::stillCase(std::string(kUv1Members) + R"(, "render": {"path": ")" +
                                          path + R"("})",
                                      std::string("uv1_") + path);
    expectUv1Maps(test::renderStill(spec), spec, path);
  }
}

TEST(MaterialMaps, TheTracerShadesTheSameMaps) {
  const auto spec = test::stillCase(kUv1Members, "uv1_traced");
  const test::TracedAndRaster r = test::traceEveryPixel(kUv1Members);
  expectUv1Maps(r.traced, spec, "traced");
  for (const float x : {-1.2f, 0.0f, 1.2f}) {
    const Quarters q = quarters(spec, x, 0.9f);
    test::expectTracedMatchesRaster(r, q.topRight.x, q.topRight.y, "top of quad at " + std::to_string(x));
    test::expectTracedMatchesRaster(r, q.bottomLeft.x, q.bottomLeft.y,
                                    "bottom of quad at " + std::to_string(x));
  }
}

const char* kUnlitScene = R"("scene": {"gltf": "scenes/unlit.gltf"},
    "camera": {"position": [0, 1.0, 3.5], "target": [0, 0.9, 0]})";
// The adaptive tracer shades without shadows (the case check refuses both together).
const std::string kUnlitMembers =
    std::string(kUnlitScene) + R"(, "lighting": {"direction": [0.0, -0.5, -1.0], "shadows": true})";

// The texels of unlit.gltf's 2x2 texture (sRGB) times the base colour factor (1, 0.8, 0.6).
float unlitTexel(int i, int j, int c) {
  static const int texels[2][2][3] = {{{200, 60, 40}, {60, 200, 90}},
                                      {{50, 90, 220}, {230, 230, 230}}};
  const float factor[3] = {1.0f, 0.8f, 0.6f};
  return float(scene::srgbToLinear(texels[j][i][c] / 255.0)) * factor[c];
}

void expectUnlit(const Image& im, const spec::CaseSpec& spec, const std::string& path) {
  // Texel rows: the top half of the quad (y above 0.9) is row 0. The bar's shadow crosses the
  // top half at y 1.0; y 1.3 is in the light.
  for (const float y : {1.3f, 1.0f, 0.65f})
    for (int i = 0; i < 2; ++i) {
      const test::Pixel p = test::pixelOf(spec, {0.7f - 0.25f + 0.5f * float(i), y, 0.0f});
      for (int c = 0; c < 3; ++c) {
        const float want = unlitTexel(i, y > 0.9f ? 0 : 1, c);
        // lavapipe's sRGB decode is within 0.3% of the exact curve.
        EXPECT_NEAR(value(im, p, c), want, 5e-3f * want + 2e-4f)
            << path << ": unlit texel " << i << " at y " << y << " channel " << c;
      }
    }
  // The lit twin is shaded, and shadowed where the unlit one is not.
  const test::Pixel lit = test::pixelOf(spec, {-0.95f, 1.3f, 0.0f}),
                    shadowed = test::pixelOf(spec, {-0.95f, 1.0f, 0.0f});
  EXPECT_LT(value(im, shadowed, 0), 0.8f * value(im, lit, 0)) << path << ": the bar's shadow";
  EXPECT_GT(std::abs(value(im, lit, 0) - unlitTexel(0, 0, 0)), 0.02f) << path << ": lit differs";
}

TEST(MaterialMaps, UnlitShowsTheBaseColourUnshadedOnEveryPath) {
  for (const char* path : {"forward", "deferred"}) {
    const auto spec = test::stillCase(kUnlitMembers + R"(, "render": {"path": ")" +
                                          path + R"("})",
                                      std::string("unlit_") + path);
    expectUnlit(test::renderStill(spec), spec, path);
  }
  const auto spec = test::stillCase(kUnlitScene, "unlit_traced");
  const test::TracedAndRaster r = test::traceEveryPixel(kUnlitScene);
  for (const float x : {0.45f, 0.95f}) {
    const test::Pixel p = test::pixelOf(spec, {x, 0.65f, 0.0f});
    test::expectTracedMatchesRaster(r, p.x, p.y, "unlit quad");
  }
}

}  // namespace
}  // namespace taa
