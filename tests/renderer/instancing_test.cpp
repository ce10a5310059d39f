// EXT_mesh_gpu_instancing (cases/scenes/instancing.gltf): six single-sided boxes on a ring
// under a node that turns about +Y at 90 degrees a second (rotation keys one second apart,
// interpolated by slerp). Every instance is drawn, the mirrored one (x scale -0.3) shows its
// outside, and every box pixel's velocity is the analytic motion of that point, which needs
// each instance's own previous transform. Before issue 25 the file was refused (the
// extension is required).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/gltf_loader.h"
#include "script/frame_state.h"
#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The ring node's transform at `t` seconds: translate (0, 0.6, 0), turn pi/2 * t about +Y.
glm::dmat4 ring(double t) {
  return glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, 0.6, 0.0)), kPi / 2.0 * t,
                     glm::dvec3(0.0, 1.0, 0.0));
}

spec::CaseSpec instancingCase() {
  return test::caseFromJson(R"({
    "scene": {"gltf": "scenes/instancing.gltf", "animation_offset_s": 0.3},
    "camera": {"position": [0, 2.2, 3.4], "target": [0, 0.5, 0]},
    "jitter": {"pattern": "none"}, "taa": {"mode": "off"}, "script": {"frames": 3},
    "output": {"frames": [2], "aux": ["depth", "velocity", "material_id"]}
  })",
                            "instancing");
}

TEST(Instancing, TheLoaderReadsEachInstanceTransform) {
  scene::Scene s;
  s.models.push_back(
      scene::loadGltf(std::filesystem::path(TAA_SOURCE_DIR) / "cases/scenes/instancing.gltf", s));
  const scene::Model& m = s.models[0];
  ASSERT_EQ(m.nodes[0].instances.size(), 6u);
  for (int k = 0; k < 6; ++k) {
    const glm::mat4& i = m.nodes[0].instances[size_t(k)];
    const double a = k * kPi / 3.0;
    EXPECT_NEAR(i[3][0], 1.2 * std::cos(a), 1e-5) << k;
    EXPECT_NEAR(i[3][2], 1.2 * std::sin(a), 1e-5) << k;
    EXPECT_NEAR(glm::determinant(glm::mat3(i)), k == 5 ? -0.027 : 0.027, 1e-5) << k;
  }
  EXPECT_EQ(scene::poseModel(s, 0, 0.0).size(), 7u) << "six instances and the floor";
}

TEST(Instancing, EveryInstanceIsDrawnOutsideOutWithItsOwnVelocity) {
  const auto spec = instancingCase();
  const auto records = test::renderCase(spec);
  const FrameRecord& r = records.back();
  const auto s = script::frameState(spec, r.frame);
  const Image& depth = test::auxImage(r, "depth");
  const Image& velocity = test::auxImage(r, "velocity");
  const Image& ids = test::auxImage(r, "material_id");
  const glm::dmat4 vp(s.camera.viewProjection), inv = glm::inverse(vp);
  const glm::dmat4 prevVp(s.prevCamera.viewProjection);
  const glm::dvec2 size(s.renderSize);
  const glm::dmat4 now = ring(s.worldAnimTime), before = ring(s.prevWorldAnimTime);
  auto project = [&](const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 c = m * glm::dvec4(p, 1.0);
    return glm::dvec3(glm::dvec2(c) / c.w * 0.5 + 0.5, c.z / c.w) * glm::dvec3(size, 1.0);
  };
  // Each instance's centre shows a box, nearer than the centre itself (reversed Z: larger
  // depth is nearer): the camera sees its outside, the mirrored one's too.
  for (int k = 0; k < 6; ++k) {
    const double a = k * kPi / 3.0;
    const glm::dvec3 centre(now * glm::dvec4(1.2 * std::cos(a), 0.0, 1.2 * std::sin(a), 1.0));
    const glm::dvec3 p = project(vp, centre);
    const int x = int(p.x), y = int(p.y);
    EXPECT_EQ(ids.at(x, y, 1), 0.0f) << "instance " << k << " covers its centre";
    EXPECT_GT(depth.at(x, y), p.z) << "instance " << k << " shows its near side";
  }
  int pixels = 0;
  double worst = 0.0, fastest = 0.0;
  for (int y = 0; y < depth.height; ++y)
    for (int x = 0; x < depth.width; ++x) {
      if (ids.at(x, y, 1) != 0.0f) continue;  // material 0: the boxes
      const glm::dvec2 pixel(x + 0.5, y + 0.5);
      const glm::dvec4 w = inv * glm::dvec4(pixel / size * 2.0 - 1.0, depth.at(x, y), 1.0);
      const glm::dvec3 local(glm::inverse(now) * glm::dvec4(glm::dvec3(w) / w.w, 1.0));
      const glm::dvec2 expected =
          pixel - glm::dvec2(project(prevVp, glm::dvec3(before * glm::dvec4(local, 1.0))));
      const glm::dvec2 got(velocity.at(x, y, 0), velocity.at(x, y, 1));
      worst = std::max(worst, glm::length(got - expected));
      fastest = std::max(fastest, glm::length(expected));
      ++pixels;
    }
  std::printf("%d box pixels: worst velocity error %.2e px, motion up to %.2f px\n", pixels, worst,
              fastest);
  EXPECT_GT(pixels, 300);
  EXPECT_GT(fastest, 1.0) << "the boxes move";
  EXPECT_LT(worst, 2e-2);
}

// The tracer winds a mirrored instance's triangles back to counter-clockwise fronts, as the
// raster's mirrored draw does: the single-sided mirrored box shows its outside to a ray too.
TEST(Instancing, TheTracerSeesTheMirroredBoxAsTheRasterDoes) {
  const std::string members = R"("scene": {"gltf": "scenes/instancing.gltf", "animation_offset_s": 0.3},
    "camera": {"position": [0, 2.2, 3.4], "target": [0, 0.5, 0]})";
  const auto spec = test::stillCase(members, "instancing_traced");
  const double a = 5 * kPi / 3.0, t = script::frameState(spec, 0).worldAnimTime;
  const glm::dvec3 mirrored(ring(t) * glm::dvec4(1.2 * std::cos(a), 0.0, 1.2 * std::sin(a), 1.0));
  const test::TracedAndRaster r = test::traceEveryPixel(members);
  const test::Pixel p = test::pixelOf(spec, glm::vec3(mirrored));
  test::expectTracedMatchesRaster(r, p.x, p.y, "the mirrored box");
}

}  // namespace
}  // namespace taa
