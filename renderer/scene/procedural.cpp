#include "scene/procedural.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include "scene/procedural_detail.h"
#include "scene/scene_error.h"
#include "scene/textures.h"

namespace taa::scene {
namespace detail {

void groundRect(MeshBuilder& b, glm::vec2 c, glm::vec2 half, float uvPerUnit) {
  b.rect({c.x, 0.0f, c.y}, {1, 0, 0}, {0, 0, -1}, half.x, half.y, 2.0f * half * uvPerUnit);
}

glm::vec3 hashedDirXZ(uint32_t i, uint32_t salt) {
  // Rejection keeps the direction uniform in angle; the bound keeps it total.
  for (uint32_t k = 0; k < 16; ++k) {
    const float x = 2.0f * hashUnit(hash3(i, salt * 31u + k, kSeedLayout)) - 1.0f;
    const float z = 2.0f * hashUnit(hash3(i, salt * 31u + k, kSeedLayout + 1)) - 1.0f;
    const float len2 = x * x + z * z;
    if (len2 > 0.01f && len2 <= 1.0f) return glm::vec3(x, 0.0f, z) / std::sqrt(len2);
  }
  return {1.0f, 0.0f, 0.0f};
}

float hashedRange(uint32_t i, uint32_t salt, float lo, float hi) {
  return lo + (hi - lo) * hashUnit(hash3(i, salt, kSeedLayout + 2));
}

std::vector<int> buildCheckerboard(Scene& s) {
  const int tex = addTexture(s, checkerTexture(256, 8, {230, 230, 230, 255}, {38, 38, 38, 255}));
  MeshBuilder ground(s, "checker_ground");
  ground.setMaterial(addMaterial(s, glm::vec4(1.0f), tex));
  groundRect(ground, {0.0f, -20.0f}, {40.0f, 40.0f}, 0.25f);  // 0.5-unit cells
  MeshBuilder boxes(s, "boxes");
  struct Box {
    glm::vec3 lo, hi, color;
  };
  const Box kBoxes[] = {
      {{-2.2f, 0.0f, -1.0f}, {-1.2f, 1.0f, 0.0f}, {0.80f, 0.15f, 0.10f}},
      {{0.8f, 0.0f, -2.5f}, {2.0f, 1.6f, -1.3f}, {0.10f, 0.30f, 0.80f}},
      {{-0.4f, 0.0f, -6.0f}, {0.4f, 2.5f, -5.2f}, {0.90f, 0.75f, 0.10f}},
      {{3.0f, 0.0f, -10.0f}, {4.5f, 3.0f, -8.5f}, {0.15f, 0.60f, 0.20f}},
      {{-5.5f, 0.0f, -14.0f}, {-3.5f, 2.0f, -12.0f}, {0.70f, 0.70f, 0.72f}},
  };
  for (const Box& b : kBoxes) {
    boxes.setMaterial(addMaterial(s, glm::vec4(b.color, 1.0f)));
    boxes.box(b.lo, b.hi, 0.0f, false);
  }
  return {ground.finish(), boxes.finish()};
}

std::vector<int> buildQuad(Scene& s) {
  const int tex = addTexture(s, checkerTexture(64, 8, {240, 240, 240, 255}, {200, 40, 30, 255}));
  MeshBuilder quad(s, "quad");
  quad.setMaterial(addMaterial(s, glm::vec4(1.0f), tex));
  quad.rect({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.5f, 0.5f);
  return {quad.finish()};
}

std::vector<int> buildOpenArea(Scene& s) {
  const int grass =
      addTexture(s, groundTexture(128, kSeedGround, {52, 78, 36, 255}, {112, 138, 70, 255}));
  const int concrete =
      addTexture(s, groundTexture(64, kSeedConcrete, {120, 118, 112, 255}, {180, 176, 168, 255}));
  const int crate = addTexture(s, checkerTexture(64, 4, {220, 220, 215, 255}, {170, 40, 32, 255}));
  MeshBuilder ground(s, "open_ground");
  ground.setMaterial(addMaterial(s, glm::vec4(1.0f), grass));
  groundRect(ground, {0.0f, 0.0f}, {200.0f, 200.0f}, 0.25f);
  MeshBuilder props(s, "pillars_and_crates");
  const int pillarMat = addMaterial(s, glm::vec4(1.0f), concrete);
  const int crateMat = addMaterial(s, glm::vec4(1.0f), crate);
  // Rings of objects at geometrically growing radii surround the origin, so a camera
  // turning on the spot always sees something near, middle and far.
  const glm::vec2 camera(0.0f, 6.0f);
  float radius = 2.5f;
  for (uint32_t ring = 0; ring < 12; ++ring, radius *= 1.4f) {
    for (uint32_t k = 0; k < 4; ++k) {
      const uint32_t id = ring * 4 + k;
      glm::vec2 p(0.0f);
      bool ok = false;
      for (uint32_t attempt = 0; attempt < 8 && !ok; ++attempt) {
        const glm::vec3 d = hashedDirXZ(id, 1 + attempt);
        p = glm::vec2(d.x, d.z) * radius;
        // Keep the camera and its line of sight to the target clear.
        ok =
            glm::length(p - camera) > 2.5f && !(std::fabs(p.x) < 1.5f && p.y > -0.5f && p.y < 7.0f);
      }
      if (!ok) continue;
      if (id % 2 == 0) {
        const float half = hashedRange(id, 2, 0.2f, 0.35f), height = hashedRange(id, 3, 2.0f, 6.0f);
        props.setMaterial(pillarMat);
        props.box({p.x - half, 0.0f, p.y - half}, {p.x + half, height, p.y + half}, 0.5f, false);
      } else {
        const float half = hashedRange(id, 4, 0.4f, 1.0f);
        props.setMaterial(crateMat);
        props.box({p.x - half, 0.0f, p.y - half}, {p.x + half, 2.0f * half, p.y + half}, 0.0f,
                  false);
      }
    }
  }
  return {ground.finish(), props.finish()};
}

}  // namespace detail

Model buildProceduralScene(spec::BuiltinScene which, Scene& scene) {
  using spec::BuiltinScene;
  std::vector<int> meshes;
  switch (which) {
    case BuiltinScene::Checkerboard:
      meshes = detail::buildCheckerboard(scene);
      break;
    case BuiltinScene::Wires:
      meshes = detail::buildWires(scene);
      break;
    case BuiltinScene::Fence:
      meshes = detail::buildFence(scene);
      break;
    case BuiltinScene::Foliage:
      meshes = detail::buildFoliage(scene);
      break;
    case BuiltinScene::RoughFloor:
      meshes = detail::buildRoughFloor(scene);
      break;
    case BuiltinScene::OpenArea:
      meshes = detail::buildOpenArea(scene);
      break;
    case BuiltinScene::Quad:
      meshes = detail::buildQuad(scene);
      break;
    case BuiltinScene::None:
      throw SceneError(
          "built-in scene 'none' has no geometry; set scene.builtin to a scene or give scene.gltf");
  }
  return flatModel(scene, std::string("builtin:") + spec::enumToString(which), meshes);
}

Model buildMoverShape(spec::MoverShape shape, const glm::vec3& color, Scene& scene) {
  MeshBuilder b(scene, shape == spec::MoverShape::Sphere ? "sphere" : "cube");
  b.setMaterial(addMaterial(scene, glm::vec4(color, 1.0f)));
  switch (shape) {
    case spec::MoverShape::Cube:
      b.box(glm::vec3(-0.5f), glm::vec3(0.5f));
      break;
    case spec::MoverShape::Sphere:
      b.sphere(glm::vec3(0.0f), 0.5f, 24, 16);
      break;
    case spec::MoverShape::Gltf:
      throw SceneError("mover shape 'gltf' is not a built-in shape; load it with loadGltf()");
  }
  const int mesh = b.finish();
  return flatModel(scene, std::string("mover:") + spec::enumToString(shape), {mesh});
}

size_t triangleCount(const Scene& scene, int mesh) {
  size_t n = 0;
  for (const Primitive& p : scene.meshes[size_t(mesh)].primitives) n += p.indexCount / 3;
  return n;
}

}  // namespace taa::scene
