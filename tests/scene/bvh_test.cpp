// The adaptive tracer's BVH: closest hits through the tree equal brute force over
// every triangle (t, triangle and barycentrics, bit for bit) on thousands of hashed
// rays over random soups, degenerate stacks and the built-in scenes; continued rays
// meet every surface in (t, triangle) order; builds are deterministic.
#include "scene/bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <glm/geometric.hpp>

#include "frame/draw_list.h"
#include "passes/adaptive/trace_geometry.h"
#include "scene/build_scene.h"
#include "script/frame_state.h"
#include "support/gpu.h"
#include "support/noise.h"

namespace taa::scene {
namespace {

using test::hashUnit;

glm::vec3 hashVec(uint32_t seed, int i, int slot, glm::vec3 lo, glm::vec3 hi) {
  return lo + (hi - lo) * glm::vec3(hashUnit(seed, i, slot, 0), hashUnit(seed, i, slot, 1),
                                    hashUnit(seed, i, slot, 2));
}

std::vector<Triangle> randomSoup(uint32_t seed, int count, float size) {
  std::vector<Triangle> tris;
  for (int i = 0; i < count; ++i) {
    const glm::vec3 c = hashVec(seed, i, 0, glm::vec3(-10.0f), glm::vec3(10.0f));
    tris.push_back({c + hashVec(seed, i, 1, glm::vec3(-size), glm::vec3(size)),
                    c + hashVec(seed, i, 2, glm::vec3(-size), glm::vec3(size)),
                    c + hashVec(seed, i, 3, glm::vec3(-size), glm::vec3(size))});
  }
  return tris;
}

// Rays from around the triangles' bounds toward points inside them, plus some
// axis-aligned ones (zero direction components exercise the slab test's guard).
std::vector<Ray> raysThrough(const std::vector<Triangle>& tris, uint32_t seed, int count) {
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const auto& t : tris)
    for (const auto& v : {t.v0, t.v1, t.v2}) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
  const glm::vec3 pad = (hi - lo) * 0.5f + 1.0f;
  std::vector<Ray> rays;
  for (int i = 0; i < count; ++i) {
    Ray r;
    r.origin = hashVec(seed, i, 0, lo - pad, hi + pad);
    if (i % 8 == 7) {
      r.dir = glm::vec3(0.0f);
      r.dir[i % 3] = (i & 16) ? 1.0f : -1.0f;
    } else {
      r.dir = hashVec(seed, i, 1, lo, hi) - r.origin;
    }
    if (i % 5 == 4) r.tMax = 0.5f;
    rays.push_back(r);
  }
  return rays;
}

void expectSameHit(const Hit& bvh, const Hit& brute, int ray) {
  ASSERT_EQ(bvh.triangle, brute.triangle) << "ray " << ray;
  if (!brute.valid()) return;
  EXPECT_EQ(std::memcmp(&bvh.t, &brute.t, sizeof(float)), 0) << "ray " << ray;
  EXPECT_EQ(bvh.u, brute.u) << "ray " << ray;
  EXPECT_EQ(bvh.v, brute.v) << "ray " << ray;
}

// Returns the number of rays that hit something.
int compareAll(const std::vector<Triangle>& tris, const std::vector<Ray>& rays) {
  const Bvh bvh = buildBvh(tris);
  int hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit a = traceBvh(bvh, tris, rays[i]);
    const Hit b = traceBruteForce(tris, rays[i]);
    expectSameHit(a, b, int(i));
    hits += b.valid() ? 1 : 0;
  }
  return hits;
}

TEST(Bvh, ClosestHitEqualsBruteForceOnRandomSoups) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    const auto tris = randomSoup(seed, 1500, seed == 3 ? 4.0f : 0.8f);
    const int hits = compareAll(tris, raysThrough(tris, seed + 100, 3000));
    EXPECT_GT(hits, 600) << "seed " << seed;  // many rays hit, so the check has teeth
  }
}

TEST(Bvh, CoincidentCentroidsSplitByMedianAndStayShallow) {
  // 2000 triangles with the same centroid and bounds: SAH finds no split.
  std::vector<Triangle> tris;
  for (int i = 0; i < 2000; ++i) {
    const float z = float(i) * 0.0f;
    tris.push_back({{-1.0f, -1.0f, z}, {1.0f, -1.0f, z}, {0.0f, 2.0f, z}});
  }
  const Bvh bvh = buildBvh(tris);
  EXPECT_LE(bvhDepth(bvh), 16);
  compareAll(tris, raysThrough(tris, 7, 500));
  // Coplanar ties: the lowest triangle index wins, through the tree and without it.
  Ray r;
  r.origin = {0.0f, 0.0f, 5.0f};
  r.dir = {0.0f, 0.0f, -1.0f};
  EXPECT_EQ(traceBvh(bvh, tris, r).triangle, 0u);
}

TEST(Bvh, DepthStaysWithinTheTraversalStack) {
  // A long thin strip of slivers: unbalanced SAH splits fall back to median below depth 40.
  std::vector<Triangle> tris;
  for (int i = 0; i < 20000; ++i) {
    const float x = std::pow(1.001f, float(i));
    tris.push_back({{x, 0.0f, 0.0f}, {x * 1.0001f, 1.0f, 0.0f}, {x, 0.0f, 1.0f}});
  }
  EXPECT_LT(bvhDepth(buildBvh(tris)), 63);
}

TEST(Bvh, ContinuedRaysMeetEverySurfaceInOrder) {
  const auto tris = randomSoup(11, 800, 3.0f);
  const Bvh bvh = buildBvh(tris);
  int longest = 0;
  for (const Ray& ray : raysThrough(tris, 12, 300)) {
    HitKey after;
    int layers = 0;
    for (;; ++layers) {
      const Hit a = traceBvh(bvh, tris, ray, after);
      const Hit b = traceBruteForce(tris, ray, after);
      ASSERT_EQ(a.triangle, b.triangle);
      if (!a.valid()) break;
      ASSERT_TRUE(hitAfter(a.t, a.triangle, after));
      after = {a.t, a.triangle};
    }
    longest = std::max(longest, layers);
  }
  EXPECT_GT(longest, 3);
}

TEST(Bvh, BuildIsDeterministic) {
  const auto tris = randomSoup(21, 3000, 1.0f);
  const Bvh a = buildBvh(tris), b = buildBvh(tris);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)), 0);
  EXPECT_EQ(a.order, b.order);
  EXPECT_TRUE(buildBvh({}).nodes.empty());
  EXPECT_FALSE(traceBvh(buildBvh({}), {}, Ray{}).valid());
}

// World triangles of a built-in scene at frame 0, movers included.
std::vector<Triangle> sceneTriangles(const std::string& json) {
  const auto spec = test::caseFromJson(json, "bvh");
  const Scene scene = buildScene(spec);
  const DrawList draws = buildDrawList(scene, script::frameState(spec, 0));
  std::vector<Triangle> tris;
  collectTriangles(scene, draws, false, tris, nullptr, nullptr);
  collectTriangles(scene, draws, true, tris, nullptr, nullptr);
  return tris;
}

TEST(Bvh, ClosestHitEqualsBruteForceOnBuiltinScenes) {
  for (const char* builtin : {"wires", "fence", "foliage", "checkerboard", "rough_floor"}) {
    const std::string json =
        std::string(R"({"scene": {"builtin": ")") + builtin +
        R"("}, "movers": [{"shape": "sphere", "start": [0, 0.5, 1], "end": [1, 0.5, 1]}]})";
    const auto tris = sceneTriangles(json);
    ASSERT_GT(tris.size(), 100u) << builtin;
    // Camera-like rays: from around the default eye into the scene.
    std::vector<Ray> rays;
    for (int i = 0; i < 1500; ++i) {
      Ray r;
      r.origin = glm::vec3(0.0f, 1.6f, 6.0f) + hashVec(5, i, 0, glm::vec3(-1.0f), glm::vec3(1.0f));
      r.dir =
          hashVec(6, i, 1, glm::vec3(-8.0f, -2.0f, -20.0f), glm::vec3(8.0f, 6.0f, 0.0f)) - r.origin;
      rays.push_back(r);
    }
    EXPECT_GT(compareAll(tris, rays), 300) << builtin;
  }
}

}  // namespace
}  // namespace taa::scene
