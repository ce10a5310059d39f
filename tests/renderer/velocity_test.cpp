// The G-buffer's velocity equals the analytic screen motion of the surface seen at
// each pixel: reconstruct the point from depth, move it back with last frame's
// object and camera transforms, project, and compare.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <glm/gtc/matrix_inverse.hpp>

#include "script/frame_state.h"
#include "support/gpu.h"

namespace taa {
namespace {

struct VelocityChecked {
  int pixels = 0;
  double worst = 0.0;      // largest |measured - analytic| in pixels
  double maxMotion = 0.0;  // largest analytic motion: the test must see real motion
};

// Compares every pixel of `frame` against the analytic motion; sky pixels use the
// view direction alone (rotation only).
VelocityChecked checkVelocity(const spec::CaseSpec& spec, const FrameRecord& r) {
  const auto s = script::frameState(spec, r.frame);
  const Image& depth = test::auxImage(r, "depth");
  const Image& velocity = test::capturedImage(r, Capture::Velocity);
  const Image& ids = test::capturedImage(r, Capture::Ids);
  const glm::dmat4 inv = glm::inverse(glm::dmat4(s.camera.viewProjection));
  const glm::dmat4 prevVp(s.prevCamera.viewProjection);
  const glm::dvec2 size(s.renderSize);
  VelocityChecked out;
  for (int y = 0; y < depth.height; y += 3)
    for (int x = 0; x < depth.width; x += 3) {
      const glm::dvec2 pixel(x + 0.5, y + 0.5);
      const glm::dvec2 ndc = pixel / size * 2.0 - 1.0;
      const double d = depth.at(x, y);
      glm::dvec2 prevPixel;
      if (d == 0.0) {  // sky: a direction, moved by the camera's rotation only
        const glm::dmat4 rot = glm::dmat4(s.camera.projection) * glm::dmat4(glm::dmat3(glm::dmat4(s.camera.view)));
        const glm::dmat4 prevRot =
            glm::dmat4(s.prevCamera.projection) * glm::dmat4(glm::dmat3(glm::dmat4(s.prevCamera.view)));
        glm::dvec4 p = glm::inverse(rot) * glm::dvec4(ndc, 0.5, 1.0);
        const glm::dvec3 dir = glm::normalize(glm::dvec3(p) / p.w);
        const glm::dvec4 c = prevRot * glm::dvec4(dir, 0.0);
        prevPixel = (glm::dvec2(c) / c.w * 0.5 + 0.5) * size;
      } else {
        glm::dvec4 w = inv * glm::dvec4(ndc, d, 1.0);
        glm::dvec3 world = glm::dvec3(w) / w.w;
        if (ids.at(x, y, 2) > 0.5f) {  // a mover: carry the point back with its own motion
          for (size_t i = 0; i < s.movers.size(); ++i) {
            const glm::dvec3 local = glm::dvec3(glm::inverse(glm::dmat4(s.movers[i])) * glm::dvec4(world, 1.0));
            if (glm::all(glm::lessThanEqual(glm::abs(local), glm::dvec3(0.5 + 1e-3)))) {
              world = glm::dvec3(glm::dmat4(s.prevMovers[i]) * glm::dvec4(local, 1.0));
              break;
            }
          }
        }
        const glm::dvec4 c = prevVp * glm::dvec4(world, 1.0);
        prevPixel = (glm::dvec2(c) / c.w * 0.5 + 0.5) * size;
      }
      const glm::dvec2 expected = pixel - prevPixel;
      const glm::dvec2 got(velocity.at(x, y, 0), velocity.at(x, y, 1));
      if (std::getenv("TAA_TEST_VERBOSE") && glm::length(got - expected) > 1e-3)
        std::printf("pixel %d,%d depth %g expected %g,%g got %g,%g\n", x, y, d, expected.x, expected.y, got.x, got.y);
      out.worst = std::max(out.worst, glm::length(got - expected));
      out.maxMotion = std::max(out.maxMotion, glm::length(expected));
      ++out.pixels;
    }
  return out;
}

// Motions stay below one pixel per frame so that RG16F stores them to 2^-12 px and
// the comparison measures the renderer, not the format.
const char* kVelocityBase = R"({
  "scene": {"builtin": "checkerboard"},
  "jitter": {"pattern": "none"},
  "taa": {"mode": "off"},
  "script": {"frames": 4},
  "output": {"frames": [3], "aux": ["depth", "velocity", "material_id"]},
  %s
})";

spec::CaseSpec velocityCase(const std::string& extra) {
  char buf[2048];
  std::snprintf(buf, sizeof(buf), kVelocityBase, extra.c_str());
  return test::caseFromJson(buf, "velocity");
}

TEST(Velocity, StaticGeometryUnderStrafingCameraMatchesAnalyticMotion) {
  const auto spec = velocityCase(R"("camera": {"strafe": {"speed": 0.5}})");
  const auto frames = test::renderCase(spec);
  const auto c = checkVelocity(spec, frames[3]);
  EXPECT_GT(c.pixels, 5000);
  EXPECT_GT(c.maxMotion, 0.3);
  EXPECT_LT(c.worst, 1e-3);
}

TEST(Velocity, RotatingCameraMatchesAnalyticMotionIncludingSky) {
  const auto spec = velocityCase(R"("camera": {"rotate": {"yaw_deg_per_s": 6.0}})");
  const auto frames = test::renderCase(spec);
  const auto c = checkVelocity(spec, frames[3]);
  EXPECT_GT(c.pixels, 5000);
  EXPECT_GT(c.maxMotion, 0.3);
  EXPECT_LT(c.worst, 1e-3);
}

TEST(Velocity, MovingObjectUnderMovingCameraMatchesAnalyticMotion) {
  const auto spec = velocityCase(
      R"("camera": {"strafe": {"speed": 0.3}},
         "movers": [{"shape": "cube", "start": [-1, 0.6, 2], "end": [1, 0.6, 2], "speed": 0.6,
                     "rotation_speed_deg": 5, "rotation_axis": [0, 1, 0]}])");
  const auto frames = test::renderCase(spec);
  // The cube must actually be on screen and moving, or the test proves nothing.
  const Image& ids = test::capturedImage(frames[3], Capture::Ids);
  int moverPixels = 0;
  for (int y = 0; y < ids.height; ++y)
    for (int x = 0; x < ids.width; ++x) moverPixels += ids.at(x, y, 2) > 0.5f;
  EXPECT_GT(moverPixels, 200);
  const auto c = checkVelocity(spec, frames[3]);
  EXPECT_GT(c.maxMotion, 0.3);
  EXPECT_LT(c.worst, 1e-3);
}

TEST(Velocity, IsZeroForAStaticCameraAndScene) {
  const auto spec = velocityCase(R"("camera": {})");
  const auto frames = test::renderCase(spec);
  const Image& v = test::capturedImage(frames[3], Capture::Velocity);
  // Rounding of the two (identical) projections may differ by an ulp once fused.
  for (float value : v.data) ASSERT_LT(std::fabs(value), 1e-4f);
}

}  // namespace
}  // namespace taa
