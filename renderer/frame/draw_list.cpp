#include "frame/draw_list.h"

#include <algorithm>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/matrix.hpp>

namespace taa {

namespace {

// Extends the last draw by `d` when `d` is its next instance of the same primitive. Only
// consecutive draws join, so the raster order of every triangle stays what it was. Deformed
// draws read their own vertices each, and a mirrored instance flips the front face.
bool extendsLast(std::vector<Draw>& draws, const Draw& d) {
  if (draws.empty()) return false;
  Draw& last = draws.back();
  if (last.mesh != d.mesh || last.primitive != d.primitive || last.deformedVertex >= 0 ||
      d.deformedVertex >= 0 || last.mirrored != d.mirrored ||
      last.instance + last.instanceCount != d.instance)
    return false;
  last.instanceCount += d.instanceCount;
  return true;
}

}  // namespace

DrawList buildDrawList(const scene::Scene& scene, const script::FrameState& state) {
  DrawList out;
  struct Sortable {
    Draw draw;
    float distance;
    size_t order;
  };
  std::vector<Sortable> blended;
  uint32_t objectId = 0;
  for (int m = 0; m < int(scene.models.size()); ++m) {
    // models[0] is the static world; model m > 0 is mover m - 1.
    const bool isMover = m > 0;
    const glm::mat4 place = isMover ? state.movers[m - 1] : glm::mat4(1.0f);
    const glm::mat4 prevPlace = isMover ? state.prevMovers[m - 1] : glm::mat4(1.0f);
    const double animTime = isMover ? state.moverAnimTime[m - 1] : state.worldAnimTime;
    const double prevAnimTime = isMover ? state.prevMoverAnimTime[m - 1] : state.prevWorldAnimTime;
    const auto now = scene::poseModel(scene, m, animTime);
    const auto before = scene::poseModel(scene, m, prevAnimTime);
    const bool animated = scene::modelAnimates(scene.models[size_t(m)]);
    // Grown once per model rather than doubled as it fills: a copy less of every instance
    // at the peak.
    out.instances.reserve(out.instances.size() + now.size());
    out.dynamic.reserve(out.dynamic.size() + now.size());
    for (size_t i = 0; i < now.size(); ++i, ++objectId) {
      const bool deformed = now[i].deformed();
      gpu::InstanceData inst{};
      inst.model = place * now[i].transform;
      inst.prevModel = prevPlace * before[i].transform;
      inst.normalMatrix = glm::mat4(glm::inverseTranspose(glm::mat3(inst.model)));
      const auto& mesh = scene.meshes[now[i].mesh];
      inst.ids = glm::uvec4(objectId, isMover ? 1 : 0, deformed ? 1 : 0, mesh.vertexColors ? 1 : 0);
      const auto instance = uint32_t(out.instances.size());
      out.instances.push_back(inst);
      out.dynamic.push_back(isMover || animated || deformed);
      int32_t deformedBase = -1;
      if (deformed) {
        deformedBase = int32_t(out.deformed.size());
        const std::vector<scene::Vertex> a = scene::deformVertices(scene, now[i]);
        const std::vector<scene::Vertex> b = scene::deformVertices(scene, before[i]);
        out.deformed.insert(out.deformed.end(), a.begin(), a.end());
        for (const scene::Vertex& v : b) out.deformedPrev.emplace_back(v.position, 1.0f);
      }
      for (int p = 0; p < int(mesh.primitives.size()); ++p) {
        Draw d{instance, 1, now[i].mesh, p, -1, glm::determinant(glm::mat3(inst.model)) < 0.0f};
        if (deformed)
          d.deformedVertex =
              deformedBase + mesh.primitives[p].vertexOffset - int32_t(mesh.firstVertex);
        const auto& material = scene.materials[mesh.primitives[p].material];
        if (material.alphaMode == scene::AlphaMode::Blend) {
          const glm::vec3 centre = glm::vec3(inst.model * glm::vec4((mesh.boundsMin + mesh.boundsMax) * 0.5f, 1.0f));
          blended.push_back({d, glm::length(centre - state.camera.position), blended.size()});
        } else if (!extendsLast(out.opaque, d)) {
          out.opaque.push_back(d);
        }
      }
    }
  }
  // Far to near; equal distances keep scene order so the result never depends on sort internals.
  std::sort(blended.begin(), blended.end(), [](const Sortable& a, const Sortable& b) {
    return a.distance != b.distance ? a.distance > b.distance : a.order < b.order;
  });
  for (const auto& b : blended) out.blended.push_back(b.draw);
  return out;
}

std::vector<Draw> singleInstanceDraws(const std::vector<Draw>& draws) {
  std::vector<Draw> out;
  for (const Draw& d : draws)
    for (uint32_t k = 0; k < d.instanceCount; ++k) {
      Draw one = d;
      one.instance = d.instance + k;
      one.instanceCount = 1;
      out.push_back(one);
    }
  return out;
}

size_t deformedVertexCount(const scene::Scene& scene) {
  size_t n = 0;
  for (int m = 0; m < int(scene.models.size()); ++m)
    for (const scene::MeshDraw& d : scene::poseModel(scene, m, 0.0))
      if (d.deformed()) n += scene.meshes[size_t(d.mesh)].vertexCount;
  return n;
}

}  // namespace taa
