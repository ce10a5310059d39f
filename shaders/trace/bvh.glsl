// Closest-hit traversal of the CPU-built BVHs (renderer/scene/bvh.cpp holds the same
// rules and is tested against brute force). Hits are ordered by (t, triangle index);
// a traversal returns the least hit after `after`, so a ray continued past an
// alpha-masked or blended surface meets every surface once, in order.
#ifndef TAA_TRACE_BVH_GLSL
#define TAA_TRACE_BVH_GLSL

struct Hit {
  float t;
  uint tri;  // TRACE_NO_ROOT: none
  float u, v;
};

bool hitAfter(float t, uint tri, float afterT, uint afterTri) {
  return t > afterT || (t == afterT && tri > afterTri);
}

bool closer(float t, uint tri, Hit best) { return t < best.t || (t == best.t && tri < best.tri); }

// Moller-Trumbore, both faces.
bool intersectTriangle(vec3 o, vec3 d, TraceTriangle tri, out float t, out float u, out float v) {
  t = u = v = 0.0;
  vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  vec3 p = cross(d, e2);
  float det = dot(e1, p);
  if (det == 0.0) return false;
  float inv = 1.0 / det;
  vec3 s = o - tri.v0;
  u = dot(s, p) * inv;
  if (u < 0.0 || u > 1.0) return false;
  vec3 q = cross(s, e1);
  v = dot(d, q) * inv;
  if (v < 0.0 || u + v > 1.0) return false;
  t = dot(e2, q) * inv;
  return t >= 0.0;
}

// The far distance widened by 2 gamma(3) (Ize): rounding never culls a box that a
// triangle inside it is hit in.
bool hitsBox(vec3 o, vec3 inv, BvhNode n, float tMin, float tMax) {
  vec3 a = (n.lo - o) * inv, b = (n.hi - o) * inv;
  vec3 near = min(a, b), far = max(a, b);
  float tNear = max(max(near.x, near.y), max(near.z, tMin));
  float tFar = min(min(far.x, far.y), min(far.z, tMax)) * 1.0000008;
  return tNear <= tFar;
}

vec3 safeInverse(vec3 d) {
  const float kTiny = 1e-20;
  vec3 tiny = mix(vec3(kTiny), vec3(-kTiny), lessThan(d, vec3(0.0)));
  return 1.0 / mix(d, tiny, lessThan(abs(d), vec3(kTiny)));
}

// A child's box is tested where its parent is popped, and only a box the ray enters is pushed
// (the farther one first): under llvmpipe's lanes every loop iteration costs the whole group,
// and popping boxes only to find them missed cost adaptive_wires' trace pass 16% more. Which
// boxes are entered moves with best.t, never the result: a box holding the closest hit passes.
void traverse(uint root, vec3 o, vec3 d, float tMax, float afterT, uint afterTri, inout Hit best) {
  if (root == TRACE_NO_ROOT) return;
  vec3 inv = safeInverse(d);
  float tMin = max(afterT, 0.0);
  if (!hitsBox(o, inv, nodes[root], tMin, min(best.t, tMax))) return;
  uint stack[64];
  int top = 0;
  stack[top++] = root;
  while (top > 0) {
    BvhNode n = nodes[stack[--top]];
    if (n.count > 0u) {
      // Tested again: best.t may have shrunk since the parent pushed it, and a leaf's
      // triangles cost more than its box.
      if (!hitsBox(o, inv, n, tMin, min(best.t, tMax))) continue;
      for (uint i = n.first; i < n.first + n.count; ++i) {
        float t, u, v;
        if (!intersectTriangle(o, d, triangles[i], t, u, v)) continue;
        if (t > tMax || !hitAfter(t, i, afterT, afterTri) || !closer(t, i, best)) continue;
        best = Hit(t, i, u, v);
      }
      continue;
    }
    BvhNode l = nodes[n.first], r = nodes[n.first + 1u];
    float far = min(best.t, tMax);
    bool hitL = hitsBox(o, inv, l, tMin, far), hitR = hitsBox(o, inv, r, tMin, far);
    bool leftFirst = dot((l.lo + l.hi) - (r.lo + r.hi), d) < 0.0;
    uint first = leftFirst ? n.first : n.first + 1u, second = leftFirst ? n.first + 1u : n.first;
    if (leftFirst ? hitR : hitL) stack[top++] = second;
    if (leftFirst ? hitL : hitR) stack[top++] = first;
  }
}

// The static world's BVH and the movers' (rebuilt every frame), as one scene.
Hit closestHit(vec3 o, vec3 d, float tMax, float afterT, uint afterTri) {
  Hit best = Hit(uintBitsToFloat(0x7f800000u), TRACE_NO_ROOT, 0.0, 0.0);  // t = +inf
  traverse(trace.roots.x, o, d, tMax, afterT, afterTri, best);
  traverse(trace.roots.y, o, d, tMax, afterT, afterTri, best);
  return best;
}

#endif
