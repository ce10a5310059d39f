// One header for C++ and GLSL: binding indices, specialization-constant ids and the
// layout of every uniform, storage and push-constant block, so the two never drift.
// Blocks hold only vec4/mat4/uvec4-sized members (or 4-byte scalars in groups of
// four), so std140/std430 and the C++ layout agree without padding rules.
#ifdef __cplusplus
#pragma once
#include <glm/glm.hpp>
#include <cstdint>
namespace taa::gpu {
using vec2 = glm::vec2;
using vec4 = glm::vec4;
using mat4 = glm::mat4;
using uvec4 = glm::uvec4;
using uint = uint32_t;
#define TAA_BLOCK(name) struct name
#else
#define TAA_BLOCK(name) struct name
#endif

// ---- G-buffer raster pass (gbuffer.vert/.frag, sky.vert/.frag) ----
#define GBUF_BINDING_FRAME 0
#define GBUF_BINDING_INSTANCES 1
#define GBUF_BINDING_TEXTURE 2

// Fragment outputs; a case allocates only the targets it needs and the rest are discarded.
#define GBUF_OUT_COLOR 0
#define GBUF_OUT_VELOCITY 1
#define GBUF_OUT_NORMAL 2
#define GBUF_OUT_IDS 3
#define GBUF_OUT_ALBEDO 4
#define GBUF_OUT_COUNT 5

#define GBUF_SPEC_DEFERRED 0  // write albedo for the deferred lighting pass instead of shading

TAA_BLOCK(FrameUniforms) {
  mat4 viewProj;              // jittered: what is rasterised
  mat4 viewProjNoJitter;      // velocity is measured without jitter
  mat4 prevViewProjNoJitter;
  mat4 invViewProjNoJitter;   // reconstructs world positions from depth
  mat4 skyInvViewProj;        // rotation-only inverse: view direction of a sky pixel
  mat4 skyPrevViewProj;       // rotation-only previous view-projection: sky velocity
  vec4 cameraPos;             // xyz
  vec4 lightDir;              // xyz: unit vector towards the light; w: intensity
  vec4 lightColor;            // rgb; w: specular weight
  vec4 ambient;               // rgb; w: shininess
  vec4 renderSize;            // width, height, 1/width, 1/height
  vec4 jitter;                // xy: this frame's jitter in pixels (image moves by it); zw: 0
};

TAA_BLOCK(InstanceData) {
  mat4 model;
  mat4 prevModel;
  mat4 normalMatrix;  // inverse transpose of model, upper 3x3
  uvec4 ids;          // x: object id (stable across frames); yzw: 0
};

TAA_BLOCK(DrawPush) {
  uint instance;
  uint material;
  float alphaCutoff;  // < 0: no alpha test
  float lodBias;
  vec4 baseColor;     // linear RGBA factor
};

#ifdef __cplusplus
static_assert(sizeof(FrameUniforms) == 6 * 64 + 6 * 16);
static_assert(sizeof(InstanceData) == 3 * 64 + 16);
static_assert(sizeof(DrawPush) == 32);
}  // namespace taa::gpu
#endif
