// A bounding volume hierarchy over world-space triangles, built on the CPU for the
// adaptive pass's compute-shader tracer (lavapipe has no ray-tracing pipelines), and
// a CPU closest-hit traversal with the same rules as shaders/trace/bvh.glsl, so the
// structure can be tested against brute force without a GPU.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <limits>
#include <vector>

namespace taa::scene {

struct Triangle {
  glm::vec3 v0, v1, v2;
};

// 32 bytes, the layout of BvhNode in shaders/common/shared.h. Inner nodes have
// count 0 and their children at `first` and `first + 1`; leaves hold triangles
// [first, first + count) of the BVH's triangle order.
struct BvhNode {
  glm::vec3 lo{0.0f};
  uint32_t first = 0;
  glm::vec3 hi{0.0f};
  uint32_t count = 0;
};
static_assert(sizeof(BvhNode) == 32);

struct Bvh {
  std::vector<BvhNode> nodes;   // nodes[0] is the root (absent for no triangles)
  std::vector<uint32_t> order;  // leaf slot -> index into the triangles it was built from
};

// Binned SAH (16 bins per axis, leaves of at most 4 triangles where SAH allows,
// median split when centroids coincide). Deterministic: every tie goes to the lower
// axis, bin and index, partitions are stable, and no threads are involved.
Bvh buildBvh(const std::vector<Triangle>& triangles);

struct Ray {
  glm::vec3 origin{0.0f};
  glm::vec3 dir{0.0f, 0.0f, -1.0f};  // need not be unit length: t is in units of dir
  float tMax = std::numeric_limits<float>::infinity();
};

// Hits are totally ordered by (t, triangle). A traversal returns the least hit
// greater than `after`; continuing a ray past a rejected hit (an alpha-masked texel)
// is a second traversal with `after` set to that hit, which visits every surface
// once, in order, even where two triangles share a t.
struct Hit {
  float t = std::numeric_limits<float>::infinity();
  uint32_t triangle = UINT32_MAX;  // index into the triangles the BVH was built from
  float u = 0.0f, v = 0.0f;        // barycentrics of v1 and v2
  bool valid() const { return triangle != UINT32_MAX; }
};

struct HitKey {
  float t = -std::numeric_limits<float>::infinity();
  uint32_t triangle = 0;
};

bool hitAfter(float t, uint32_t triangle, const HitKey& after);

// Moller-Trumbore, both faces. t, u, v are valid when it returns true.
bool intersectTriangle(const Ray& ray, const Triangle& tri, float& t, float& u, float& v);

Hit traceBvh(const Bvh& bvh, const std::vector<Triangle>& triangles, const Ray& ray,
             const HitKey& after = {});
Hit traceBruteForce(const std::vector<Triangle>& triangles, const Ray& ray,
                    const HitKey& after = {});

// Depth of the tree (1 for a single leaf); for logs and tests.
int bvhDepth(const Bvh& bvh);

}  // namespace taa::scene
