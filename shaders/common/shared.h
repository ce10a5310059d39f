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

// Bits of a G-buffer fragment-shader variant (VARIANT_MASK): which optional outputs exist.
#define GBUF_OUTPUT_VELOCITY 1
#define GBUF_OUTPUT_NORMAL 2
#define GBUF_OUTPUT_IDS 4
#define GBUF_OUTPUT_ALBEDO 8

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
  uvec4 ids;          // x: object id (stable across frames), y: 1 for movers
};

// The ids target packs mover flag (bit 31), object id (bits 16-30), material (0-15).
#define IDS_MOVER_BIT 0x80000000u
#define IDS_SKY 0x7fffffffu

TAA_BLOCK(DrawPush) {
  uint instance;
  uint material;
  float alphaCutoff;  // < 0: no alpha test
  float lodBias;
  vec4 baseColor;     // linear RGBA factor
};

// ---- Temporal resolve (taa_resolve.comp and shaders/taa/*.glsl) ----
#define TAA_BINDING_UNIFORMS 0
#define TAA_BINDING_COLOR 1         // current frame (render size), colour or motion-blurred colour
#define TAA_BINDING_DEPTH 2
#define TAA_BINDING_VELOCITY 3
#define TAA_BINDING_IDS 4
#define TAA_BINDING_NORMAL 5
#define TAA_BINDING_HISTORY 6       // previous output (output size), linear sampler
#define TAA_BINDING_PREV_DEPTH 7
#define TAA_BINDING_PREV_NORMAL 8
#define TAA_BINDING_PREV_IDS 9
#define TAA_BINDING_PREV_VELOCITY 10
#define TAA_BINDING_HISTORY_OUT 11  // new history = resolve output (storage)
#define TAA_BINDING_DEBUG_OUT 12    // debug view (storage), when debug.output is set
#define TAA_BINDING_COUNT 13

#define TAA_SPEC_MODE 0             // 0 pass-through, 1 basic, 2 full
#define TAA_SPEC_HAS_HISTORY 1      // false on frame 0, cuts and scripted resets
#define TAA_SPEC_TONE_WEIGHT 2      // ToneWeight
#define TAA_SPEC_USE_VELOCITY 3     // UseVelocity
#define TAA_SPEC_VELOCITY_SAMPLING 4
#define TAA_SPEC_HISTORY_FILTER 5
#define TAA_SPEC_REJECT_OFFSCREEN 6
#define TAA_SPEC_DEPTH_CULLING 7
#define TAA_SPEC_CONSISTENCY 8
#define TAA_SPEC_ANTI_GHOSTING 9
#define TAA_SPEC_RECTIFY 10         // Rectify
#define TAA_SPEC_VARIANCE_CLIP 11
#define TAA_SPEC_SHAPED 12
#define TAA_SPEC_YCOCG 13
#define TAA_SPEC_SHRINK_CHROMA 14
#define TAA_SPEC_LUMA_WEIGHT 15
#define TAA_SPEC_VELOCITY_ALPHA 16
#define TAA_SPEC_REDUCE_BLEND 17
#define TAA_SPEC_VELOCITY_IN_ALPHA 18
#define TAA_SPEC_UPSAMPLE 19
#define TAA_SPEC_DEBUG 20           // DebugOutput

TAA_BLOCK(TaaUniforms) {
  mat4 invViewProj;       // current, un-jittered: world position from depth
  mat4 prevViewProj;      // previous, un-jittered: where that position was
  vec4 renderSize;        // this frame's render size: w, h, 1/w, 1/h
  vec4 prevRenderSize;    // last frame's render size (previous G-buffer content)
  vec4 outputSize;        // w, h, 1/w, 1/h
  vec4 jitter;            // xy: this frame's jitter (render pixels); zw: 0
  vec4 blend;             // alpha, rejection alpha, alpha_min, alpha_max
  vec4 limits;            // variance gamma, depth threshold, velocity_alpha_px, debug scale
  vec4 planes;            // near, far, consistency depth tolerance, consistency normal dot
};

// ---- Post passes around the resolve (motion_blur, sharpen, cas, fxaa .comp) ----
// Each reads through a nearest clamp sampler (texelFetch only) and writes RGBA16F.
#define MB_BINDING_COLOR 0      // render-size colour
#define MB_BINDING_VELOCITY 1   // RG16F, render pixels, current minus previous position
#define MB_BINDING_DEPTH 2      // reversed Z (1 near, 0 far)
#define MB_BINDING_OUT 3
#define MB_BINDING_COUNT 4

#define MB_SPEC_SAMPLES 0            // taps along the velocity (post.motion_blur_samples)
#define MB_SPEC_VELOCITY_IN_ALPHA 1  // alpha = speed in render pixels instead of 1

#define POST_BINDING_INPUT 0   // sharpen, cas, fxaa: the image they filter
#define POST_BINDING_OUTPUT 1
#define POST_BINDING_COUNT 2

// Push constants of every post pass: the valid region and the pass's parameters.
TAA_BLOCK(PostPush) {
  vec4 size;    // valid width, height, 1/width, 1/height (top-left of the images)
  vec4 params;  // motion_blur: x scale, y depth tolerance; sharpen: x amount;
                // cas: x negative-lobe peak (-1/8 .. -1/5); fxaa: x edge threshold,
                // y edge threshold min, z subpixel amount
};

// ---- TSCMAA (tscmaa_edges.comp, tscmaa_cmaa.comp, tscmaa_taa.comp, shaders/tscmaa/) ----
// One eye at a time: colour and depth are the eye's G-buffer (eye-local pixels); the
// mask and CMAA images hold both eyes side by side (eye-local pixel + eye offset); the
// history is per eye.
#define TSCMAA_BINDING_UNIFORMS 0
#define TSCMAA_BINDING_COLOR 1         // the eye's colour, nearest sampler
#define TSCMAA_BINDING_MASK 2          // r32ui storage: TSCMAA_EDGE_* bits per pixel
#define TSCMAA_BINDING_EDGE_LIST 3     // storage buffer: every edge pixel
#define TSCMAA_BINDING_TAA_LIST 4      // storage buffer: the TAA share of them
#define TSCMAA_BINDING_CMAA 5          // CMAA result: storage (cmaa pass), sampled (taa pass)
#define TSCMAA_BINDING_TAA_UNIFORMS 6  // TaaUniforms of the eye (taa pass)
#define TSCMAA_BINDING_DEPTH 7         // the eye's depth (taa pass)
#define TSCMAA_BINDING_HISTORY 8       // the eye's previous output, linear sampler (taa pass)
#define TSCMAA_BINDING_HISTORY_OUT 9   // the eye's new output (taa pass)
#define TSCMAA_BINDING_COUNT 10

// Mask bits: an edge on each side of the pixel, and membership of the TAA share.
#define TSCMAA_EDGE_LEFT 1u
#define TSCMAA_EDGE_TOP 2u
#define TSCMAA_EDGE_RIGHT 4u
#define TSCMAA_EDGE_BOTTOM 8u
#define TSCMAA_EDGES 15u
#define TSCMAA_TAA 16u

// Invocations per group of the indirect passes; the edge pass counts groups as it appends.
#define TSCMAA_LIST_GROUP 64u

TAA_BLOCK(TscmaaUniforms) {
  vec4 params;  // edge threshold, non-dominant edge removal, blurriness, taa share
  vec4 size;    // eye width, height, 1/width, 1/height
  uvec4 eye;    // x: the eye's x offset in the side-by-side images; y: taa share as a 16-bit
                // fixed-point bound (hash < y selects); zw: 0
};

// The first 16 bytes of an edge list: the VkDispatchIndirectCommand of the pass over
// it, then the entry count. Entries (x | y << 16) follow.
TAA_BLOCK(EdgeListHeader) {
  uint groupsX;
  uint groupsY;
  uint groupsZ;
  uint count;
};

#ifdef __cplusplus
static_assert(sizeof(PostPush) == 32);
static_assert(sizeof(TaaUniforms) == 2 * 64 + 7 * 16);
static_assert(sizeof(FrameUniforms) == 6 * 64 + 6 * 16);
static_assert(sizeof(InstanceData) == 3 * 64 + 16);
static_assert(sizeof(DrawPush) == 32);
static_assert(sizeof(TscmaaUniforms) == 48);
static_assert(sizeof(EdgeListHeader) == 16);
}  // namespace taa::gpu
#endif
