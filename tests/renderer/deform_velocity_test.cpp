// The G-buffer's velocity on skinned and morphed geometry equals the analytic motion of
// the bend quads (cases/scenes/{skinned,morphed}_quad.gltf): a surface point at local
// (x, y) sits at y + (x + 0.5) * 0.8 * t, so carrying it back one frame needs the
// previous frame's joints or weights; the rigid node transform alone would miss it.
#include <gtest/gtest.h>

#include <cstdio>
#include <glm/gtc/matrix_inverse.hpp>

#include "script/frame_state.h"
#include "support/gpu.h"

namespace taa {
namespace {

struct Checked {
  int pixels = 0;        // mover pixels compared
  double worst = 0.0;    // largest |measured - analytic| in pixels
  double maxBend = 0.0;  // largest motion from the bend alone: must be real
};

constexpr double kRate = 0.8;  // units of rise per second at x = +0.5

Checked checkBend(const spec::CaseSpec& spec, const FrameRecord& r) {
  const auto s = script::frameState(spec, r.frame);
  const Image& depth = test::auxImage(r, "depth");
  const Image& velocity = test::capturedImage(r, Capture::Velocity);
  const Image& ids = test::capturedImage(r, Capture::Ids);
  const glm::dmat4 inv = glm::inverse(glm::dmat4(s.camera.viewProjection));
  const glm::dmat4 prevVp(s.prevCamera.viewProjection);
  const glm::dvec2 size(s.renderSize);
  const glm::dmat4 mover(s.movers[0]), prevMover(s.prevMovers[0]);
  const double lift = kRate * s.moverAnimTime[0], prevLift = kRate * s.prevMoverAnimTime[0];
  Checked out;
  for (int y = 0; y < depth.height; ++y)
    for (int x = 0; x < depth.width; ++x) {
      if (ids.at(x, y, 2) < 0.5f) continue;  // the bend quad is the only mover
      const glm::dvec2 pixel(x + 0.5, y + 0.5);
      const glm::dvec4 w = inv * glm::dvec4(pixel / size * 2.0 - 1.0, depth.at(x, y), 1.0);
      glm::dvec3 local = glm::dvec3(glm::inverse(mover) * glm::dvec4(glm::dvec3(w) / w.w, 1.0));
      const double bend = local.x + 0.5;
      local.y += bend * (prevLift - lift);
      auto project = [&](const glm::dmat4& vp, const glm::dvec3& p) {
        const glm::dvec4 c = vp * glm::dvec4(p, 1.0);
        return (glm::dvec2(c) / c.w * 0.5 + 0.5) * size;
      };
      const glm::dvec2 expected =
          pixel - project(prevVp, glm::dvec3(prevMover * glm::dvec4(local, 1.0)));
      const glm::dvec2 got(velocity.at(x, y, 0), velocity.at(x, y, 1));
      if (std::getenv("TAA_TEST_VERBOSE") && glm::length(got - expected) > 1e-3)
        std::printf("pixel %d,%d expected %g,%g got %g,%g\n", x, y, expected.x, expected.y, got.x,
                    got.y);
      out.worst = std::max(out.worst, glm::length(got - expected));
      // The same point without the bend's own motion: what a rigid-only velocity would give.
      glm::dvec3 rigid = local;
      rigid.y -= bend * (prevLift - lift);
      const glm::dvec2 rigidPrev = project(prevVp, glm::dvec3(prevMover * glm::dvec4(rigid, 1.0)));
      out.maxBend = std::max(
          out.maxBend,
          glm::length(project(prevVp, glm::dvec3(prevMover * glm::dvec4(local, 1.0))) - rigidPrev));
      ++out.pixels;
    }
  std::printf("%d bend-quad pixels: worst velocity error %.2e px, bend motion up to %.3f px\n",
              out.pixels, out.worst, out.maxBend);
  return out;
}

spec::CaseSpec bendCase(const std::string& asset) {
  return test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 4},
    "camera": {"strafe": {"speed": 0.2}},
    "movers": [{"shape": "gltf", "gltf": "scenes/)" +
                                asset + R"(", "size": 2.5,
                "start": [-0.4, 0.3, 2.5], "end": [0.4, 0.3, 2.5], "speed": 0.3,
                "animation_speed": 0.3, "animation_offset_s": 1.0}],
    "output": {"frames": [3], "aux": ["depth", "velocity", "material_id"]}
  })",
                            "deform_velocity");
}

TEST(DeformVelocity, SkinnedQuadMatchesAnalyticMotion) {
  const auto spec = bendCase("skinned_quad.gltf");
  const auto frames = test::renderCase(spec);
  const Checked c = checkBend(spec, frames[3]);
  EXPECT_GT(c.pixels, 2000);
  EXPECT_GT(c.maxBend, 0.2) << "the bend itself must move pixels, or the test proves nothing";
  EXPECT_LT(c.worst, 1e-3);
}

TEST(DeformVelocity, MorphedQuadMatchesAnalyticMotion) {
  const auto spec = bendCase("morphed_quad.gltf");
  const auto frames = test::renderCase(spec);
  const Checked c = checkBend(spec, frames[3]);
  EXPECT_GT(c.pixels, 2000);
  EXPECT_GT(c.maxBend, 0.2) << "the bend itself must move pixels, or the test proves nothing";
  EXPECT_LT(c.worst, 1e-3);
}

}  // namespace
}  // namespace taa
