// The outdoor test scenes modelled on the seed testbed's problem cases: thin wires,
// a foreshortened fence, alpha-tested foliage and a rough high-variance floor.
#include <cmath>
#include <glm/geometric.hpp>

#include "scene/procedural.h"
#include "scene/procedural_detail.h"
#include "scene/textures.h"

namespace taa::scene {
namespace {

using detail::hashedDirXZ;
using detail::hashedRange;

// Wire poles: pairs at x = +-7, wires spanning between them across the view.
constexpr float kPoleX = 7.0f;
constexpr float kPoleZ[] = {-2.0f, -7.0f, -13.0f};
constexpr float kPoleTop = 4.6f;
// 0.012 circumradius: at the nearest span (about 8 units deep) a cable is under half a
// pixel wide at 320x180, and 1 px would need a depth of 3.7 units.
constexpr float kCableRadius = 0.012f;
constexpr int kCableSegments = 16;

std::vector<glm::vec3> sagging(const glm::vec3& a, const glm::vec3& b, float sag) {
  std::vector<glm::vec3> pts;
  for (int i = 0; i <= kCableSegments; ++i) {
    const float t = float(i) / float(kCableSegments);
    pts.push_back(a + (b - a) * t - glm::vec3(0.0f, sag * 4.0f * t * (1.0f - t), 0.0f));
  }
  return pts;
}

int groundMesh(Scene& s, const char* name, int texture, glm::vec2 center, glm::vec2 half,
               float uvPerUnit) {
  MeshBuilder g(s, name);
  g.setMaterial(addMaterial(s, glm::vec4(1.0f), texture));
  detail::groundRect(g, center, half, uvPerUnit);
  return g.finish();
}

int grassTexture(Scene& s) {
  return addTexture(
      s, groundTexture(128, detail::kSeedGround, {44, 72, 30, 255}, {100, 132, 62, 255}));
}

// Smooth hashed value noise in world units, for the floor's displacement.
float lattice(int i, int j, uint32_t salt) {
  return hashUnit(hash3(uint32_t(i), uint32_t(j), detail::kSeedLayout + salt)) - 0.5f;
}
float worldNoise(float x, float z, float cell, uint32_t salt) {
  const float u = x / cell, v = z / cell;
  const int i = int(std::floor(u)), j = int(std::floor(v));
  auto s = [](float t) { return t * t * (3.0f - 2.0f * t); };
  const float fu = s(u - float(i)), fv = s(v - float(j));
  const float a = lattice(i, j, salt) + (lattice(i + 1, j, salt) - lattice(i, j, salt)) * fu;
  const float b =
      lattice(i, j + 1, salt) + (lattice(i + 1, j + 1, salt) - lattice(i, j + 1, salt)) * fu;
  return a + (b - a) * fv;
}
float floorHeight(float x, float z) {
  return 0.45f * worldNoise(x, z, 1.6f, 10) + 0.16f * worldNoise(x, z, 0.6f, 11);
}

}  // namespace

std::vector<Cable> wireCables() {
  std::vector<Cable> cables;
  for (float z : kPoleZ) {
    // Three wires side by side on the crossarm and one lower, all sagging.
    for (float dz : {-0.45f, 0.0f, 0.45f})
      cables.push_back(
          {sagging({-kPoleX, kPoleTop - 0.1f, z + dz}, {kPoleX, kPoleTop - 0.1f, z + dz}, 0.45f),
           kCableRadius});
    cables.push_back(
        {sagging({-kPoleX, kPoleTop - 0.9f, z}, {kPoleX, kPoleTop - 0.9f, z}, 0.6f), kCableRadius});
  }
  // Two cables along each pole line recede from the camera and foreshorten.
  const float zNear = kPoleZ[0], zFar = kPoleZ[std::size(kPoleZ) - 1];
  for (float x : {-kPoleX, kPoleX})
    cables.push_back(
        {sagging({x, kPoleTop - 0.5f, zNear}, {x, kPoleTop - 0.5f, zFar}, 0.3f), kCableRadius});
  return cables;
}

namespace detail {

std::vector<int> buildWires(Scene& s) {
  const int ground =
      groundMesh(s, "wires_ground", grassTexture(s), {0.0f, -20.0f}, {60.0f, 60.0f}, 0.5f);
  MeshBuilder poles(s, "poles");
  poles.setMaterial(addMaterial(s, glm::vec4(0.8f, 0.75f, 0.7f, 1.0f),
                                addTexture(s, woodTexture(64, kSeedWood))));
  for (float z : kPoleZ)
    for (float x : {-kPoleX, kPoleX}) {
      poles.box({x - 0.09f, 0.0f, z - 0.09f}, {x + 0.09f, kPoleTop, z + 0.09f}, 0.0f, false);
      poles.box({x - 0.05f, kPoleTop - 0.1f, z - 0.6f}, {x + 0.05f, kPoleTop, z + 0.6f}, 0.0f,
                true);
    }
  MeshBuilder wires(s, "wires");
  wires.setMaterial(addMaterial(s, glm::vec4(0.02f, 0.02f, 0.025f, 1.0f)));
  for (const Cable& c : wireCables()) wires.tube(c.points, c.radius, 4);
  return {ground, poles.finish(), wires.finish()};
}

std::vector<int> buildFence(Scene& s) {
  const int dirt =
      addTexture(s, groundTexture(128, kSeedGround + 7, {92, 74, 54, 255}, {150, 126, 96, 255}));
  const int ground = groundMesh(s, "fence_ground", dirt, {0.0f, -20.0f}, {60.0f, 60.0f}, 0.5f);
  MeshBuilder fence(s, "fence");
  fence.setMaterial(addMaterial(s, glm::vec4(0.9f, 0.9f, 0.86f, 1.0f),
                                addTexture(s, woodTexture(64, kSeedWood))));
  // Slats 6 cm wide every 25 cm along x = -1.3: from the camera at x = 0 the fence is
  // seen at a few degrees, so the gaps shrink below a pixel within a few metres.
  auto run = [&](float x, float zFrom, float zTo, float step, float rail) {
    const int slats = int((zFrom - zTo) / step) + 1;
    for (int i = 0; i < slats; ++i) {
      const float z = zFrom - step * float(i);
      fence.box({x - 0.015f, 0.0f, z - 0.03f}, {x + 0.015f, 1.1f, z + 0.03f}, 0.0f, false);
    }
    for (float y : {0.25f, 0.8f})
      fence.box({x + rail - 0.015f, y, zTo - 0.1f}, {x + rail + 0.015f, y + 0.08f, zFrom + 0.1f},
                0.0f, true);
  };
  run(-1.3f, 4.5f, -45.0f, 0.25f, -0.03f);  // rails behind the slats, seen from inside
  run(2.6f, 2.0f, -20.0f, 0.35f, 0.03f);
  return {ground, fence.finish()};
}

std::vector<int> buildFoliage(Scene& s) {
  const int ground =
      groundMesh(s, "foliage_ground", grassTexture(s), {0.0f, -20.0f}, {60.0f, 60.0f}, 0.5f);
  const int leaf = addTexture(s, leafTexture(128, kSeedLeaf));
  MeshBuilder cards(s, "leaf_cards");
  cards.setMaterial(addMaterial(s, glm::vec4(1.0f), leaf, AlphaMode::Mask, true));
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  // Bushes of three cards crossed at 60 degrees, on a jittered 8 x 6 grid.
  constexpr float kHalfSqrt3 = 0.8660254f;
  for (uint32_t i = 0; i < 48; ++i) {
    const float gx = -7.0f + 2.0f * float(i % 8), gz = 2.5f - 3.0f * float(i / 8);
    const glm::vec3 c(gx + hashedRange(i, 10, -0.8f, 0.8f), 0.0f,
                      gz + hashedRange(i, 11, -1.2f, 1.2f));
    const float size = hashedRange(i, 12, 1.1f, 2.0f);
    const glm::vec3 d = hashedDirXZ(i, 13);
    for (int k = 0; k < 3; ++k) {
      const float cs = k == 0 ? 1.0f : -0.5f,
                  sn = k == 0 ? 0.0f : (k == 1 ? kHalfSqrt3 : -kHalfSqrt3);
      const glm::vec3 r(d.x * cs - d.z * sn, 0.0f, d.x * sn + d.z * cs);
      cards.rect(c + up * (size * 0.5f), r, up, size * 0.5f, size * 0.5f);
    }
  }
  // A small tree: trunk and a canopy of cards in hashed orientations.
  const glm::vec3 trunk(3.2f, 0.0f, -5.0f);
  MeshBuilder wood(s, "trunk");
  wood.setMaterial(addMaterial(s, glm::vec4(0.55f, 0.45f, 0.4f, 1.0f),
                               addTexture(s, woodTexture(64, kSeedWood))));
  wood.box(trunk + glm::vec3(-0.12f, 0.0f, -0.12f), trunk + glm::vec3(0.12f, 2.6f, 0.12f), 0.0f,
           false);
  for (uint32_t i = 0; i < 40; ++i) {
    const glm::vec3 o(hashedRange(i, 20, -1.3f, 1.3f), hashedRange(i, 21, 2.0f, 3.8f),
                      hashedRange(i, 22, -1.3f, 1.3f));
    const glm::vec3 r = hashedDirXZ(i, 23);
    // Tilt each card about its right axis by mixing in a hashed amount of horizontal.
    const glm::vec3 fwd = glm::cross(r, up);
    const float t = hashedRange(i, 24, -0.8f, 0.8f);
    const glm::vec3 cardUp = glm::normalize(up + fwd * t);
    cards.rect(trunk + o, r, cardUp, 0.7f, 0.7f);
  }
  return {ground, cards.finish(), wood.finish()};
}

std::vector<int> buildRoughFloor(Scene& s) {
  const int tex = addTexture(s, roughNoiseTexture(256, kSeedRough));
  MeshBuilder floor(s, "rough_floor");
  floor.setMaterial(addMaterial(s, glm::vec4(1.0f), tex));
  constexpr int kCells = 40;
  constexpr float kX0 = -16.0f, kX1 = 16.0f, kZ0 = 6.0f, kZ1 = -26.0f, kEps = 0.05f;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const float x = kX0 + (kX1 - kX0) * float(i) / kCells,
                  z = kZ0 + (kZ1 - kZ0) * float(j) / kCells;
      // Central differences of the height field give the normal without derivatives.
      const float dx = (floorHeight(x + kEps, z) - floorHeight(x - kEps, z)) / (2.0f * kEps);
      const float dz = (floorHeight(x, z + kEps) - floorHeight(x, z - kEps)) / (2.0f * kEps);
      floor.vertex({x, floorHeight(x, z), z}, glm::normalize(glm::vec3(-dx, 1.0f, -dz)),
                   {x * 0.5f, -z * 0.5f});
    }
  for (uint32_t j = 0; j < kCells; ++j)
    for (uint32_t i = 0; i < kCells; ++i) {
      const uint32_t a = j * (kCells + 1) + i, b = a + 1, c = a + kCells + 1, d = c + 1;
      // Rows advance towards -z and columns towards +x, so (a, b, d) winds CCW from above.
      floor.triangle(a, b, d);
      floor.triangle(a, d, c);
    }
  return {floor.finish()};
}

}  // namespace detail
}  // namespace taa::scene
