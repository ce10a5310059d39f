// The adaptive tracer shades what the raster shades: vertex colours (glTF COLOR_0) and
// emission (emissiveFactor times KHR_materials_emissive_strength). Every pixel is traced
// with one ray through its centre and compared with the raster's image of that centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

using test::TracedAndRaster;
using test::traceEveryPixel;

void expectSameAround(const TracedAndRaster& r, int x, int y, const char* what) {
  test::expectTracedMatchesRaster(r, x, y, what);
}

TEST(AdaptiveShading, TracedVertexColoursMatchTheRaster) {
  // cases/scenes/morphed_quad.gltf: a white material, red vertices on the left, blue on
  // the right (as tests/renderer/vertex_color_test.cpp draws it).
  const TracedAndRaster r = traceEveryPixel(R"("scene": {"builtin": "checkerboard"},
    "camera": {"position": [0, 0.8, 3], "target": [0, 0.8, 0]},
    "movers": [{"shape": "gltf", "gltf": "scenes/morphed_quad.gltf", "size": 3,
                "start": [0, 0.8, 0], "end": [0, 0.8, 0], "speed": 0, "animation_speed": 0}])");
  const int y = r.raster.height / 2, left = r.raster.width / 2 - r.raster.width / 5,
            right = r.raster.width / 2 + r.raster.width / 5;
  ASSERT_GT(r.raster.at(left, y, 0), 3.0f * r.raster.at(left, y, 2)) << "the raster is red here";
  ASSERT_GT(r.raster.at(right, y, 2), 3.0f * r.raster.at(right, y, 0)) << "and blue here";
  expectSameAround(r, left, y, "red side");
  expectSameAround(r, right, y, "blue side");
  expectSameAround(r, r.raster.width / 2, y, "middle");
}

TEST(AdaptiveShading, TracedEmissionMatchesTheRaster) {
  // cases/scenes/emissive.gltf: panels glowing (4, 2, 0.5) and (0.25, 0.5, 1), and a
  // dark one, centred at pixels x = 118, 160 and 202 from this camera.
  const TracedAndRaster r = traceEveryPixel(R"("scene": {"gltf": "scenes/emissive.gltf"},
    "camera": {"position": [0, 0.6, 3], "target": [0, 0.6, 0]})");
  ASSERT_GT(r.raster.at(118, 90, 0), 3.9f) << "the raster shows the strong panel's emission";
  expectSameAround(r, 118, 90, "strong panel");
  expectSameAround(r, 160, 90, "factor-only panel");
  expectSameAround(r, 202, 90, "dark panel");
}

}  // namespace
}  // namespace taa
