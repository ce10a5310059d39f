// Morph targets and skinning on the CPU. The renderer deforms each such mesh twice a
// frame (this frame's and the previous frame's pose), so motion vectors come from the
// previous joint matrices and weights, not from a rigid node transform.
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "scene/scene.h"

namespace taa::scene {

std::vector<Vertex> deformVertices(const Scene& scene, const MeshDraw& draw) {
  const Mesh& mesh = scene.meshes[size_t(draw.mesh)];
  std::vector<Vertex> out(scene.vertices.begin() + mesh.firstVertex,
                          scene.vertices.begin() + mesh.firstVertex + mesh.vertexCount);
  // Morph targets first (glTF: skinning applies to the morphed mesh).
  for (size_t t = 0; t < mesh.targets.size() && t < draw.weights.size(); ++t) {
    const float w = draw.weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = mesh.targets[t];
    for (size_t i = 0; i < out.size(); ++i) {
      out[i].position += w * target.position[i];
      if (!target.normal.empty()) out[i].normal += w * target.normal[i];
    }
  }
  if (!mesh.targets.empty())
    for (Vertex& v : out)
      if (glm::dot(v.normal, v.normal) > 0.0f) v.normal = glm::normalize(v.normal);
  if (draw.joints.empty() || mesh.skin.size() != out.size()) return out;
  const auto joints = uint32_t(draw.joints.size());
  for (size_t i = 0; i < out.size(); ++i) {
    const SkinWeights& sw = mesh.skin[i];
    glm::mat4 m(0.0f);
    bool any = false;
    for (int k = 0; k < 4; ++k)
      if (sw.weights[k] != 0.0f && sw.joints[k] < joints) {
        m += sw.weights[k] * draw.joints[sw.joints[k]];
        any = true;
      }
    if (!any) continue;  // a primitive of the mesh without joints stays where it is
    out[i].position = glm::vec3(m * glm::vec4(out[i].position, 1.0f));
    // Joints carry no shear in practice; the upper 3x3 then keeps normals perpendicular.
    const glm::vec3 n = glm::mat3(m) * out[i].normal;
    out[i].normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : out[i].normal;
  }
  return out;
}

}  // namespace taa::scene
