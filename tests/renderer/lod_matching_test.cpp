// LOD matching between the raster and the tracer (seed 000): render.lod0 (every lookup at
// mip 0), render.lod0_alpha_test (alpha tests read mip 0) and adaptive.aniso (anisotropy of
// the tracer's ray-differential LOD), each shown on the path it acts on.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "passes/adaptive/ray_differentials.h"
#include "scene/build_scene.h"
#include "scene/scene_error.h"
#include "support/gpu.h"

namespace taa {
namespace {

// Mean absolute luminance step between horizontal neighbours in rows [y0, y1): texture
// detail that mips would have averaged away shows up here.
double lodDetail(const Image& im, int y0, int y1) {
  double sum = 0.0;
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 1; x < im.width; ++x) {
      const auto l = [&](int px) {
        return 0.2126 * im.at(px, y, 0) + 0.7152 * im.at(px, y, 1) + 0.0722 * im.at(px, y, 2);
      };
      sum += std::abs(l(x) - l(x - 1));
      ++n;
    }
  return sum / n;
}

// A low camera over the checkerboard: the far floor's cells are far below a pixel.
// `traced`: every pixel traced with one ray (with `adaptive` members added).
Image checkerFrame(const std::string& render, bool traced = false,
                   const std::string& adaptive = "") {
  const std::string mode =
      traced ? R"("taa": {"mode": "adaptive"}, "adaptive": {"trace_all": true, "samples": 1)" +
                   (adaptive.empty() ? "" : ", " + adaptive) + "}"
             : R"("taa": {"mode": "off"})";
  const auto spec = test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
    "camera": {"position": [0, 0.4, 4], "target": [0, 0.2, -10]},
    "jitter": {"pattern": "none"}, )" + mode +
                                       (render.empty() ? "" : R"(, "render": {)" + render + "}") +
                                       R"(, "script": {"frames": 1}, "output": {"frames": [0]}})");
  return test::renderCase(spec)[0].color;
}

double lodMeanAbsDiff(const Image& a, const Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.data.size(); ++i) sum += std::abs(double(a.data[i]) - double(b.data[i]));
  return sum / double(a.data.size());
}

TEST(LodMatching, Lod0KeepsTheDetailMipsWouldAverageAwayInRasterAndTracer) {
  // Rows around the horizon: cells far smaller than a pixel.
  const Image mipped = checkerFrame("");
  const Image lod0 = checkerFrame(R"("lod0": true)");
  EXPECT_GT(lodDetail(lod0, 70, 90), 3.0 * lodDetail(mipped, 70, 90));
  // The tracer with ray-differential LOD blurs like the raster; with render.lod0 it
  // samples mip 0 like the lod0 raster.
  const Image tracedLod0 = checkerFrame(R"("lod0": true)", true);
  const Image tracedMipped = checkerFrame("", true);
  EXPECT_LT(lodMeanAbsDiff(tracedLod0, lod0), 0.5 * lodMeanAbsDiff(tracedMipped, lod0));
}

TEST(LodMatching, AnisotropicGradientsShortenTheLongerAxisUpToTheFactor) {
  const glm::vec2 size(64.0f, 64.0f);
  glm::vec2 dx(4.0f / 64.0f, 0.0f), dy(0.0f, 1.0f / 64.0f);
  const float iso = textureLod(dx, dy, size);
  EXPECT_FLOAT_EQ(iso, 2.0f);
  glm::vec2 ax = dx, ay = dy;
  anisotropicGradients(ax, ay, size, 1.0f);
  EXPECT_EQ(ax, dx);
  EXPECT_EQ(ay, dy);
  anisotropicGradients(ax, ay, size, 2.0f);
  EXPECT_NEAR(textureLod(ax, ay, size), 1.0f, 1e-6f);
  ax = dx;
  ay = dy;
  anisotropicGradients(ax, ay, size, 16.0f);  // capped by the footprint's own ratio, 4
  EXPECT_NEAR(textureLod(ax, ay, size), 0.0f, 1e-6f);
  // The longer axis may be y.
  ax = dy;
  ay = dx;
  anisotropicGradients(ax, ay, size, 2.0f);
  EXPECT_NEAR(glm::length(ay * size), 2.0f, 1e-5f);
  EXPECT_NEAR(glm::length(ax * size), 1.0f, 1e-5f);
  // A zero footprint (a triangle whose vertices share one UV) stays zero, never NaN.
  ax = ay = glm::vec2(0.0f);
  anisotropicGradients(ax, ay, size, 8.0f);
  EXPECT_EQ(ax, glm::vec2(0.0f));
  EXPECT_EQ(ay, glm::vec2(0.0f));
}

TEST(LodMatching, AnisoSharpensTheTracedFloorAtGrazingAngles) {
  const Image iso = checkerFrame("", true);
  const Image aniso = checkerFrame("", true, R"("aniso": 8)");
  EXPECT_GT(lodDetail(aniso, 70, 100), 1.2 * lodDetail(iso, 70, 100));
}

TEST(LodMatching, Lod0AlphaTestChangesTheFoliageInRasterAndTracer) {
  const auto foliage = [](bool lod0Alpha, bool traced) {
    const std::string mode =
        traced ? R"("taa": {"mode": "adaptive"}, "adaptive": {"trace_all": true, "samples": 1})"
               : R"("taa": {"mode": "off"})";
    const auto spec =
        test::caseFromJson(std::string(R"({"scene": {"builtin": "foliage"},
      "jitter": {"pattern": "none"}, )") +
                           mode + (lod0Alpha ? R"(, "render": {"lod0_alpha_test": true})" : "") +
                           R"(, "script": {"frames": 1}, "output": {"frames": [0]}})");
    return test::renderCase(spec)[0].color;
  };
  const Image raster = foliage(false, false), rasterLod0 = foliage(true, false);
  const Image traced = foliage(false, true), tracedLod0 = foliage(true, true);
  EXPECT_GT(lodMeanAbsDiff(raster, rasterLod0), 1e-3);
  EXPECT_GT(lodMeanAbsDiff(traced, tracedLod0), 1e-3);
  // Both paths test the same alpha: the traced image stays as close to the raster with the
  // key as without it.
  EXPECT_LT(lodMeanAbsDiff(tracedLod0, rasterLod0), 1.5 * lodMeanAbsDiff(traced, raster) + 1e-4);
}

TEST(LodMatching, KeysAreRefusedWhereTheyWouldNotAct) {
  auto untextured =
      test::caseFromJson(R"({"render": {"lod0_alpha_test": true}})", "lod0_alpha_checker");
  EXPECT_THROW(scene::buildScene(untextured),
               scene::SceneError);  // the checkerboard has no alpha test
  auto foliage = test::caseFromJson(
      R"({"scene": {"builtin": "foliage"}, "render": {"lod0_alpha_test": true}})");
  EXPECT_NO_THROW(scene::buildScene(foliage));
}

}  // namespace
}  // namespace taa
