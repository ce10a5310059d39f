// Internal to the procedural scenes: the per-scene builders and shared helpers,
// split over two files to keep each readable.
#pragma once

#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "scene/geometry.h"
#include "scene/scene.h"

namespace taa::scene::detail {

// Seeds for the procedural textures and layouts; changing one changes golden images.
constexpr uint32_t kSeedGround = 0x5eed0001u;
constexpr uint32_t kSeedLeaf = 0x5eed0002u;
constexpr uint32_t kSeedRough = 0x5eed0003u;
constexpr uint32_t kSeedWood = 0x5eed0004u;
constexpr uint32_t kSeedLayout = 0x5eed0005u;
constexpr uint32_t kSeedConcrete = 0x5eed0006u;

// A horizontal ground rectangle at y = 0 facing +Y, textured `uvPerUnit` times per unit.
void groundRect(MeshBuilder& b, glm::vec2 centerXZ, glm::vec2 halfXZ, float uvPerUnit);
// A unit vector in the XZ plane from a hash (no trigonometry, see textures.cpp).
glm::vec3 hashedDirXZ(uint32_t i, uint32_t salt);
float hashedRange(uint32_t i, uint32_t salt, float lo, float hi);

std::vector<int> buildCheckerboard(Scene& s);
std::vector<int> buildQuad(Scene& s);
std::vector<int> buildOpenArea(Scene& s);
std::vector<int> buildWires(Scene& s);
std::vector<int> buildFence(Scene& s);
std::vector<int> buildFoliage(Scene& s);
std::vector<int> buildRoughFloor(Scene& s);

}  // namespace taa::scene::detail
