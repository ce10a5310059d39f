#include "scene/bvh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace taa::scene {

namespace {

constexpr int kBins = 16;
constexpr uint32_t kLeafSize = 4;
constexpr uint32_t kMaxLeafSize = 16;  // a node SAH would not split may stay a leaf up to here
// Below this depth every split is a median split, which bounds the depth (and so
// the traversal stacks, 64 entries here and in the shader) by 40 + log2(triangles).
constexpr int kSahDepth = 40;

struct Box {
  glm::vec3 lo{std::numeric_limits<float>::infinity()};
  glm::vec3 hi{-std::numeric_limits<float>::infinity()};
  void grow(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  void grow(const Box& b) {
    lo = glm::min(lo, b.lo);
    hi = glm::max(hi, b.hi);
  }
  float area() const {
    if (lo.x > hi.x) return 0.0f;
    const glm::vec3 e = hi - lo;
    return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
  }
};

struct Builder {
  const std::vector<Triangle>& tris;
  std::vector<Box> boxes;
  std::vector<glm::vec3> centroids;
  Bvh bvh;

  explicit Builder(const std::vector<Triangle>& t) : tris(t) {
    for (const auto& tri : tris) {
      Box b;
      b.grow(tri.v0);
      b.grow(tri.v1);
      b.grow(tri.v2);
      boxes.push_back(b);
      centroids.push_back((b.lo + b.hi) * 0.5f);
    }
  }

  struct Split {
    int axis = -1;
    int bin = 0;  // triangles in bins [0, bin] go left
    float cost = std::numeric_limits<float>::infinity();
  };

  static int binOf(float c, float lo, float scale) {
    return std::clamp(int((c - lo) * scale), 0, kBins - 1);
  }

  Split bestSplit(uint32_t begin, uint32_t end, const Box& cb) const {
    Split best;
    for (int axis = 0; axis < 3; ++axis) {
      const float extent = cb.hi[axis] - cb.lo[axis];
      if (!(extent > 0.0f)) continue;
      const float scale = float(kBins) / extent;
      std::array<Box, kBins> bin;
      std::array<uint32_t, kBins> count{};
      for (uint32_t i = begin; i < end; ++i) {
        const uint32_t t = bvh.order[i];
        const int b = binOf(centroids[t][axis], cb.lo[axis], scale);
        bin[b].grow(boxes[t]);
        ++count[b];
      }
      // Right-to-left sweep for the right sides, then left-to-right for the costs.
      std::array<float, kBins> rightArea{};
      std::array<uint32_t, kBins> rightCount{};
      Box acc;
      uint32_t n = 0;
      for (int b = kBins - 1; b > 0; --b) {
        acc.grow(bin[b]);
        n += count[b];
        rightArea[b] = acc.area();
        rightCount[b] = n;
      }
      Box left;
      uint32_t nl = 0;
      for (int b = 0; b < kBins - 1; ++b) {
        left.grow(bin[b]);
        nl += count[b];
        if (nl == 0 || rightCount[b + 1] == 0) continue;
        const float cost = left.area() * float(nl) + rightArea[b + 1] * float(rightCount[b + 1]);
        if (cost < best.cost) best = {axis, b, cost};
      }
    }
    return best;
  }

  uint32_t partition(uint32_t begin, uint32_t end, const Box& cb, const Split& s) {
    const float scale = float(kBins) / (cb.hi[s.axis] - cb.lo[s.axis]);
    auto goesLeft = [&](uint32_t t) {
      return binOf(centroids[t][s.axis], cb.lo[s.axis], scale) <= s.bin;
    };
    auto mid = std::stable_partition(bvh.order.begin() + begin, bvh.order.begin() + end, goesLeft);
    return uint32_t(mid - bvh.order.begin());
  }

  void build(uint32_t node, uint32_t begin, uint32_t end, int depth) {
    Box bounds, cb;
    for (uint32_t i = begin; i < end; ++i) {
      bounds.grow(boxes[bvh.order[i]]);
      cb.grow(centroids[bvh.order[i]]);
    }
    bvh.nodes[node].lo = bounds.lo;
    bvh.nodes[node].hi = bounds.hi;
    const uint32_t count = end - begin;
    uint32_t mid = begin;
    if (count > kLeafSize && depth >= kSahDepth) {
      mid = begin + count / 2;
    } else if (count > kLeafSize) {
      const Split s = bestSplit(begin, end, cb);
      const bool splitPays =
          s.axis >= 0 && (s.cost < bounds.area() * float(count) || count > kMaxLeafSize);
      if (splitPays)
        mid = partition(begin, end, cb, s);
      else if (s.axis < 0 && count > kMaxLeafSize)
        mid = begin + count / 2;  // coincident centroids
    }
    if (mid == begin || mid == end) {
      bvh.nodes[node].first = begin;
      bvh.nodes[node].count = count;
      return;
    }
    const auto left = uint32_t(bvh.nodes.size());
    bvh.nodes.resize(bvh.nodes.size() + 2);
    bvh.nodes[node].first = left;
    bvh.nodes[node].count = 0;
    build(left, begin, mid, depth + 1);
    build(left + 1, mid, end, depth + 1);
  }
};

// The slab test with the far distance widened by 2 * gamma(3) (Ize, "Robust BVH ray
// traversal"), so rounding never culls a box a triangle inside it is hit in.
bool hitsBox(const glm::vec3& o, const glm::vec3& inv, const BvhNode& n, float tMin, float tMax) {
  const glm::vec3 a = (n.lo - o) * inv, b = (n.hi - o) * inv;
  const glm::vec3 near = glm::min(a, b), far = glm::max(a, b);
  const float tNear = std::max(std::max(near.x, near.y), std::max(near.z, tMin));
  const float tFar = std::min(std::min(far.x, far.y), std::min(far.z, tMax)) * 1.0000008f;
  return tNear <= tFar;
}

float safeInverse(float d) {
  constexpr float kTiny = 1e-20f;
  return 1.0f / (std::abs(d) < kTiny ? std::copysign(kTiny, d) : d);
}

bool better(float t, uint32_t tri, const Hit& best) {
  return t < best.t || (t == best.t && tri < best.triangle);
}

void consider(const Ray& ray, const Triangle& tri, uint32_t id, const HitKey& after, Hit& best) {
  float t, u, v;
  if (!intersectTriangle(ray, tri, t, u, v)) return;
  if (t > ray.tMax || !hitAfter(t, id, after) || !better(t, id, best)) return;
  best = {t, id, u, v};
}

}  // namespace

Bvh buildBvh(const std::vector<Triangle>& triangles) {
  Builder b(triangles);
  if (triangles.empty()) return {};
  b.bvh.order.resize(triangles.size());
  for (uint32_t i = 0; i < triangles.size(); ++i) b.bvh.order[i] = i;
  b.bvh.nodes.reserve(2 * triangles.size());
  b.bvh.nodes.emplace_back();
  b.build(0, 0, uint32_t(triangles.size()), 0);
  return std::move(b.bvh);
}

bool hitAfter(float t, uint32_t triangle, const HitKey& after) {
  return t > after.t || (t == after.t && triangle > after.triangle);
}

bool intersectTriangle(const Ray& ray, const Triangle& tri, float& t, float& u, float& v) {
  const glm::vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const glm::vec3 p = glm::cross(ray.dir, e2);
  const float det = glm::dot(e1, p);
  if (det == 0.0f) return false;
  const float inv = 1.0f / det;
  const glm::vec3 s = ray.origin - tri.v0;
  u = glm::dot(s, p) * inv;
  if (u < 0.0f || u > 1.0f) return false;
  const glm::vec3 q = glm::cross(s, e1);
  v = glm::dot(ray.dir, q) * inv;
  if (v < 0.0f || u + v > 1.0f) return false;
  t = glm::dot(e2, q) * inv;
  return t >= 0.0f;
}

Hit traceBvh(const Bvh& bvh, const std::vector<Triangle>& triangles, const Ray& ray,
             const HitKey& after) {
  Hit best;
  if (bvh.nodes.empty()) return best;
  const glm::vec3 inv(safeInverse(ray.dir.x), safeInverse(ray.dir.y), safeInverse(ray.dir.z));
  const float tMin = std::max(after.t, 0.0f);
  uint32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const BvhNode& n = bvh.nodes[stack[--top]];
    if (!hitsBox(ray.origin, inv, n, tMin, std::min(best.t, ray.tMax))) continue;
    if (n.count > 0) {
      for (uint32_t i = n.first; i < n.first + n.count; ++i)
        consider(ray, triangles[bvh.order[i]], bvh.order[i], after, best);
      continue;
    }
    // Visit the child on the ray's side of the split axis first (its box comes first
    // along the direction of largest extent): fewer triangles tested, same result.
    const BvhNode& l = bvh.nodes[n.first];
    const BvhNode& r = bvh.nodes[n.first + 1];
    const glm::vec3 d = (l.lo + l.hi) - (r.lo + r.hi);
    const bool leftFirst = glm::dot(d, ray.dir) < 0.0f;
    stack[top++] = leftFirst ? n.first + 1 : n.first;
    stack[top++] = leftFirst ? n.first : n.first + 1;
  }
  return best;
}

Hit traceBruteForce(const std::vector<Triangle>& triangles, const Ray& ray, const HitKey& after) {
  Hit best;
  for (uint32_t i = 0; i < triangles.size(); ++i) consider(ray, triangles[i], i, after, best);
  return best;
}

int bvhDepth(const Bvh& bvh) {
  if (bvh.nodes.empty()) return 0;
  int deepest = 0;
  std::vector<std::pair<uint32_t, int>> stack = {{0u, 1}};
  while (!stack.empty()) {
    const auto [i, d] = stack.back();
    stack.pop_back();
    deepest = std::max(deepest, d);
    if (bvh.nodes[i].count == 0) {
      stack.push_back({bvh.nodes[i].first, d + 1});
      stack.push_back({bvh.nodes[i].first + 1, d + 1});
    }
  }
  return deepest;
}

}  // namespace taa::scene
