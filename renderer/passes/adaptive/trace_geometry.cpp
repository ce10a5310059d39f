#include "passes/adaptive/trace_geometry.h"

#include <algorithm>
#include <utility>
#include <glm/mat3x3.hpp>

namespace taa {

void collectTriangles(const scene::Scene& scene, const DrawList& draws, bool movers,
                      std::vector<scene::Triangle>& triangles,
                      std::vector<gpu::TraceShading>* shading, std::vector<uint32_t>* materials) {
  // One instance each: the triangles keep the order of the instances, then the primitives.
  std::vector<Draw> all = singleInstanceDraws(draws.opaque);
  all.insert(all.end(), draws.blended.begin(), draws.blended.end());
  // Blended draws are sorted by distance each frame; triangle order must not follow.
  std::sort(all.begin(), all.end(), [](const Draw& a, const Draw& b) {
    return a.instance != b.instance
               ? a.instance < b.instance
               : (a.mesh != b.mesh ? a.mesh < b.mesh : a.primitive < b.primitive);
  });
  for (const Draw& d : all) {
    const gpu::InstanceData& inst = draws.instances[d.instance];
    if ((draws.dynamic[d.instance] != 0) != movers) continue;
    const scene::Primitive& prim = scene.meshes[d.mesh].primitives[d.primitive];
    const glm::mat3 normalMatrix(inst.normalMatrix);
    // Skinned and morphed draws: this frame's deformed vertices.
    const scene::Vertex* base = d.deformedVertex >= 0 ? &draws.deformed[size_t(d.deformedVertex)]
                                                      : &scene.vertices[size_t(prim.vertexOffset)];
    for (uint32_t k = 0; k + 2 < prim.indexCount; k += 3) {
      const scene::Vertex* v[3];
      for (int j = 0; j < 3; ++j) v[j] = &base[scene.indices[prim.firstIndex + k + uint32_t(j)]];
      // A mirrored instance's front faces wind clockwise (glTF): reordered, every triangle's
      // front winds counter-clockwise in world space, which is what the tracer tests.
      if (d.mirrored) std::swap(v[1], v[2]);
      auto world = [&](int j) { return glm::vec3(inst.model * glm::vec4(v[j]->position, 1.0f)); };
      triangles.push_back({world(0), world(1), world(2)});
      if (shading) {
        gpu::TraceShading s{};
        s.n0 = glm::vec4(normalMatrix * v[0]->normal, 0.0f);
        s.n1 = glm::vec4(normalMatrix * v[1]->normal, 0.0f);
        s.n2 = glm::vec4(normalMatrix * v[2]->normal, 0.0f);
        s.uv01 = glm::vec4(v[0]->uv, v[1]->uv);
        s.uv2 = glm::vec4(v[2]->uv, scene.meshes[d.mesh].vertexColors ? 1.0f : 0.0f, 0.0f);
        s.c0 = v[0]->color;
        s.c1 = v[1]->color;
        s.c2 = v[2]->color;
        s.uv1_01 = glm::vec4(v[0]->uv1, v[1]->uv1);
        s.uv1_2 = glm::vec4(v[2]->uv1, 0.0f, 0.0f);
        shading->push_back(s);
      }
      if (materials) materials->push_back(uint32_t(prim.material));
    }
  }
}

TraceGeometry buildTraceGeometry(const scene::Scene& scene, const DrawList& draws, bool movers,
                                 uint32_t nodeBase, uint32_t triangleBase) {
  std::vector<scene::Triangle> tris;
  std::vector<gpu::TraceShading> shading;
  std::vector<uint32_t> materials;
  collectTriangles(scene, draws, movers, tris, &shading, &materials);
  const scene::Bvh bvh = scene::buildBvh(tris);
  TraceGeometry g;
  for (const scene::BvhNode& n : bvh.nodes) {
    gpu::BvhNode out{};
    out.lo = n.lo;
    out.hi = n.hi;
    out.count = n.count;
    out.first = n.first + (n.count > 0 ? triangleBase : nodeBase);
    g.nodes.push_back(out);
  }
  for (const uint32_t i : bvh.order) {
    gpu::TraceTriangle t{};
    t.v0 = tris[i].v0;
    t.v1 = tris[i].v1;
    t.v2 = tris[i].v2;
    t.material = materials[i];
    g.triangles.push_back(t);
    g.shading.push_back(shading[i]);
  }
  return g;
}

}  // namespace taa
