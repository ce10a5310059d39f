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
using vec3 = glm::vec3;
using vec4 = glm::vec4;
using mat4 = glm::mat4;
using uvec4 = glm::uvec4;
using uint = uint32_t;
#define TAA_BLOCK(name) struct name
#else
#define TAA_BLOCK(name) struct name
#endif

#include "resolve_inputs.h"
#include "taa_settings.h"

// ---- G-buffer raster pass (gbuffer.vert/.frag, sky.vert/.frag) ----
#define GBUF_BINDING_FRAME 0
#define GBUF_BINDING_INSTANCES 1
#define GBUF_BINDING_TEXTURE 2
#define GBUF_BINDING_PREV_POSITIONS 3  // deformed vertices' positions at frame - 1
#define GBUF_BINDING_SHADOW 4          // shadow atlas (GBUF_OUTPUT_SHADOW variants only)
#define GBUF_BINDING_NORMAL_MAP 5      // normal texture (read when DrawPush emissive.w != 0)
#define GBUF_BINDING_EMISSIVE_MAP 6    // emissive texture (read with MATERIAL_EMISSIVE_MAP)
#define GBUF_BINDING_OCCLUSION_MAP 7   // occlusion texture (read with MATERIAL_OCCLUSION_MAP)

// A material's textures beyond the base colour and their UV sets (DrawPush::maps,
// TraceMaterial::maps; renderer/gpu_scene.cpp's materialMaps writes them).
#define MATERIAL_BASE_UV1 1u          // the base colour samples TEXCOORD_1
#define MATERIAL_NORMAL_UV1 2u        // the normal map samples TEXCOORD_1
#define MATERIAL_EMISSIVE_MAP 4u      // an emissive texture multiplies the emission
#define MATERIAL_EMISSIVE_UV1 8u
#define MATERIAL_OCCLUSION_MAP 16u    // an occlusion texture scales the ambient term
#define MATERIAL_OCCLUSION_UV1 32u
#define MATERIAL_UNLIT 64u            // KHR_materials_unlit: the base colour, unshaded

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
#define GBUF_OUTPUT_SHADOW 16  // not an output: samples the shadow atlas (lighting.shadows)

// ---- Cascaded shadow maps (shadow_depth.vert/.frag; read by common/shadow.glsl) ----
#define SHADOW_MAX_CASCADES 4
#define SHADOW_BINDING_INSTANCES 0
#define SHADOW_BINDING_TEXTURE 1   // base colour, for alpha-tested casters
#define DEFERRED_BINDING_SHADOW 5  // deferred_lighting.comp's shadow atlas (shadowed variant)

TAA_BLOCK(ShadowPush) {
  mat4 lightViewProj;  // world -> the cascade's clip space (orthographic, depth 0 at the light)
  uint pad0;          // draws are instanced: the instance is gl_InstanceIndex
  float alphaCutoff;  // < 0: no alpha test
  uint maps;          // MATERIAL_* bits (MATERIAL_BASE_UV1 picks the alpha test's UV set)
  uint pad1;
  vec4 baseColor;  // linear RGBA factor (its alpha takes part in the alpha test)
};

#define GBUF_SPEC_DEFERRED 0  // write albedo for the deferred lighting pass instead of shading
#define GBUF_SPEC_LOD0 1      // render.lod0: every texture lookup at mip 0
#define GBUF_SPEC_LOD0_ALPHA 2  // render.lod0_alpha_test (also shadow_depth.frag)

TAA_BLOCK(FrameUniforms) {
  mat4 viewProj;              // jittered: what is rasterised
  mat4 viewProjNoJitter;      // velocity is measured without jitter
  mat4 prevViewProjNoJitter;
  mat4 invViewProjNoJitter;   // reconstructs world positions from depth
  mat4 skyInvViewProj;        // rotation-only inverse: view direction of a sky pixel
  mat4 skyViewProj;           // rotation-only view-projection: where that direction is now
  mat4 skyPrevViewProj;       // rotation-only previous view-projection: sky velocity
  vec4 cameraPos;             // xyz
  vec4 lightDir;              // xyz: unit vector towards the light; w: intensity
  vec4 lightColor;            // rgb; w: specular weight
  vec4 ambient;               // rgb; w: shininess
  vec4 renderSize;            // width, height, 1/width, 1/height
  vec4 jitter;                // xy: this frame's jitter in pixels (image moves by it); zw: 0
  // Cascaded shadows (renderer/frame/shadow_cascades.h); all zero when lighting.shadows is off.
  mat4 shadowMatrix[SHADOW_MAX_CASCADES];  // world -> atlas uv (xy) and biased light depth (z)
  vec4 shadowSplits;        // view depth (along shadowForward) where each cascade ends
  vec4 shadowNormalOffset;  // per cascade: world distance a receiver moves along its normal
  vec4 shadowForward;       // xyz: forward of the camera the cascades fit (unit); w: cascade count
  vec4 shadowOrigin;        // xyz: that camera's position (stereo eyes share the centre's)
  vec4 shadowAtlas;         // x, y: 1 / atlas width, height; z: 1 / cascade count; w: 0
};

TAA_BLOCK(InstanceData) {
  mat4 model;
  mat4 prevModel;
  mat4 normalMatrix;  // inverse transpose of model, upper 3x3
  uvec4 ids;          // x: object id (stable across frames), y: 1 for movers, z: 1 when
                      // deformed (vertices from the deformed buffer, prevPositions by index),
                      // w: 1 when the mesh has vertex colours
};

// The ids target packs mover flag (bit 31), object id (bits 16-30), material (0-15).
#define IDS_MOVER_BIT 0x80000000u
#define IDS_SKY 0x7fffffffu

TAA_BLOCK(DrawPush) {
  uint pad2;  // draws are instanced: the instance is gl_InstanceIndex (gbuffer.vert)
  uint material;
  float alphaCutoff;  // < 0: no alpha test
  float lodBias;
  vec4 baseColor;     // linear RGBA factor
  // emissive rgb: linear radiance added to the shaded colour (0: none); w: normal-map scale
  // (material.normal_strength times the texture's scale; 0: no normal map)
  vec4 emissive;
  uint maps;                // MATERIAL_* bits
  float occlusionStrength;  // with MATERIAL_OCCLUSION_MAP: ambient *= 1 + strength * (red - 1)
  uint pad0;
  uint pad1;
};

// ---- Temporal resolve (taa_resolve.comp and shaders/taa/*.glsl) ----
// Its inputs' bindings are the rows of common/resolve_inputs.h; these are the others.
#define TAA_BINDING_UNIFORMS 0
#define TAA_BINDING_HISTORY_OUT 11  // new history = resolve output (storage)
#define TAA_BINDING_DEBUG_OUT 12    // debug view (storage), when debug.output is set
#define TAA_BINDING_REJECT_OUT 13   // R32UI why history was not used (TAA_REJECT_*), adaptive mode

// Why a pixel's history was not used: shaders/taa/rejection.glsl's verdict, written to
// TAA_BINDING_REJECT_OUT for the adaptive segmentation. Every reason from
// TAA_REJECT_FIRST_ON_SCREEN on is a test that rejected a history position on screen.
#define TAA_REJECT_NONE 0u
#define TAA_REJECT_OFFSCREEN 1u    // the reprojected position left the previous frame
#define TAA_REJECT_NO_HISTORY 2u   // frame 0, camera cut or scripted reset
#define TAA_REJECT_DEPTH 3u        // depth culling: last frame's surface there is another one
#define TAA_REJECT_GHOST 4u        // anti-ghosting: a mover's trail
#define TAA_REJECT_INCONSISTENT 5u  // geometric consistency: no tap is the same surface
#define TAA_REJECT_FIRST_ON_SCREEN TAA_REJECT_DEPTH

TAA_BLOCK(TaaUniforms) {
  mat4 invViewProj;       // current, un-jittered: world position from depth
  mat4 prevViewProj;      // previous, un-jittered: where that position was
  vec4 renderSize;        // this frame's render size: w, h, 1/w, 1/h
  vec4 prevRenderSize;    // last frame's render size (previous G-buffer content)
  vec4 outputSize;        // w, h, 1/w, 1/h
  vec4 jitter;            // xy: this frame's jitter (render pixels); z: frame index; w: 0
  vec4 view;              // near, far, debug scale, 0
  vec4 settings[TAA_SETTING_VEC4S];  // float settings at their slots (common/taa_settings.h)
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
#define POST_BINDING_MASK 2    // fxaa only: R32UI segmentation mask (read when FXAA_SPEC_MASKED)
#define POST_BINDING_COUNT 2

#define FXAA_SPEC_MASKED 0     // filter only pixels whose mask is ADAPTIVE_MASK_FXAA, copy the rest

// Push constants of every post pass: the valid region and the pass's parameters.
TAA_BLOCK(PostPush) {
  vec4 size;    // valid width, height, 1/width, 1/height (top-left of the images)
  vec4 params;  // motion_blur: x scale, y depth tolerance; sharpen: x amount;
                // cas: x negative-lobe peak (-1/8 .. -1/5); fxaa: x edge threshold,
                // y edge threshold min, z subpixel amount
};

// ---- Still-image upsampling (still_image.comp, debug.image) ----
#define STILL_BINDING_IMAGE 0  // the still image (output size), linear or nearest clamp sampler
#define STILL_BINDING_OUT 1    // the colour target
TAA_BLOCK(StillPush) {
  vec4 size;    // render width, height, 1/width, 1/height
  vec4 jitter;  // xy: the frame's jitter in render pixels (the image moves by it); zw: 0
};

// ---- Stress injection (inject.comp) ----
// The value written, in params.y; C++ passes these names, never InjectValue's order.
#define INJECT_NAN 0
#define INJECT_POS_INF 1
#define INJECT_NEG_INF 2
TAA_BLOCK(InjectPush) {
  vec4 pixels[4];  // xy and zw: two pixel coordinates each (up to 8)
  vec4 params;     // x: pixel count, y: INJECT_*
};

// ---- Adaptive ray tracing (adaptive_segmentation.comp, adaptive_trace.comp) ----
// The segmentation mask, one R32UI per output pixel.
#define ADAPTIVE_MASK_NONE 0u           // the resolve's output stands
#define ADAPTIVE_MASK_TRACE 1u          // derivatives over the threshold (or trace_all, disocclusion)
#define ADAPTIVE_MASK_TRACE_HISTORY 2u  // traced because it was marked within history_count frames
#define ADAPTIVE_MASK_FXAA 3u           // out of history and not traced

#define SEG_BINDING_UNIFORMS 0
#define SEG_BINDING_COLOR 1      // the resolve's input colour
#define SEG_BINDING_DEPTH 2
#define SEG_BINDING_NORMAL 3
#define SEG_BINDING_IDS 4
#define SEG_BINDING_REJECTION 5  // the resolve's TAA_REJECT_* image
#define SEG_BINDING_COUNTER 6    // R32UI frames left of the history count (read and written in place)
#define SEG_BINDING_MASK 7       // R32UI ADAPTIVE_MASK_*
#define SEG_BINDING_COUNTS 8     // AdaptiveCounts
#define SEG_BINDING_RESOLVED 9   // the resolve's output: the debug view's background
#define SEG_BINDING_DEBUG 10     // debug view (storage, RGBA16F)
#define SEG_BINDING_COUNT 11

#define SEG_SPEC_HAS_HISTORY 0      // false: counters restart, every pixel is out of history
#define SEG_SPEC_TRACE_ALL 1
#define SEG_SPEC_FXAA 2             // adaptive.fxaa_out_of_history
#define SEG_SPEC_TRACE_DISOCCLUDED 3
#define SEG_SPEC_DEBUG 4            // write the debug view
#define SEG_SPEC_FXAA_BORDER 5  // adaptive.fxaa_debug_border: output pixels always marked for FXAA

TAA_BLOCK(SegmentationUniforms) {
  vec4 weights;  // normal, depth, material, luminance
  vec4 params;   // threshold, history_count, near, far
  vec4 size;     // w, h, 1/w, 1/h
  vec4 pad;
};

TAA_BLOCK(AdaptiveCounts) {
  uint traced;  // pixels traced this frame (an integer sum: the same for any invocation order)
  uint fxaa;
  uint pad0;
  uint pad1;
};

#define TRACE_BINDING_FRAME 0      // FrameUniforms of the raster pass: camera and light
#define TRACE_BINDING_PARAMS 1     // TraceUniforms
#define TRACE_BINDING_NODES 2      // BvhNode[]: the static BVH, then the movers' BVH
#define TRACE_BINDING_TRIANGLES 3  // TraceTriangle[] in BVH leaf order
#define TRACE_BINDING_SHADING 4    // TraceShading[] parallel to the triangles
#define TRACE_BINDING_MATERIALS 5  // TraceMaterial[]
#define TRACE_BINDING_MASK 6
#define TRACE_BINDING_OUT 7        // the resolve's output (= next frame's history), written in place
#define TRACE_BINDING_TEXTURES 8   // sampler2D[TRACE_MAX_TEXTURES]
#define TRACE_BINDING_COUNT 9

#define TRACE_MAX_TEXTURES 16  // adaptive_trace.comp has one switch case per slot
#define TRACE_MAX_SAMPLES 16
#define TRACE_NO_ROOT 0xffffffffu

#define TRACE_SPEC_SAMPLES 0
#define TRACE_SPEC_RAY_LOD 1
#define TRACE_SPEC_ANISO 2       // adaptive.aniso (float)
#define TRACE_SPEC_LOD0_ALPHA 3  // render.lod0_alpha_test
#define TRACE_SPEC_TEXTURE_SLOTS 4  // the slots the scene's materials use (1..TRACE_MAX_TEXTURES)

// Inner nodes: count 0, children at first and first + 1. Leaves: triangles
// [first, first + count). (A uint after a vec3 shares its 16 bytes in std430 and C++.)
TAA_BLOCK(BvhNode) {
  vec3 lo;
  uint first;
  vec3 hi;
  uint count;
};

TAA_BLOCK(TraceTriangle) {
  vec3 v0;  // world space
  uint material;
  vec3 v1;
  uint pad0;
  vec3 v2;
  uint pad1;
};

TAA_BLOCK(TraceShading) {
  vec4 n0;    // world-space vertex normals as the vertex shader outputs them (not normalised)
  vec4 n1;
  vec4 n2;
  vec4 uv01;  // uv0.xy, uv1.xy
  vec4 uv2;   // xy; z: 1 when the mesh has vertex colours (the raster's InstanceData ids.w)
  vec4 c0;    // linear RGBA vertex colours (glTF COLOR_0), multiplying the base colour when uv2.z is 1
  vec4 c1;
  vec4 c2;
  vec4 uv1_01;  // TEXCOORD_1 of vertices 0 and 1
  vec4 uv1_2;   // TEXCOORD_1 of vertex 2 (xy)
};

TAA_BLOCK(TraceMaterial) {
  vec4 baseColor;     // linear RGBA factor
  float alphaCutoff;  // < 0: no alpha test
  uint texture;       // slot in the texture array
  uint blend;         // 1: alpha-blended ("over", composited front to back along the ray)
  uint doubleSided;   // 0: rays pass through the back faces, as the raster culls them
  vec4 emissive;      // rgb: linear radiance added to the shaded colour (0: none); w: occlusion strength
  uint maps;             // MATERIAL_* bits, as the raster's DrawPush::maps
  uint emissiveTexture;  // slot of the emissive texture (with MATERIAL_EMISSIVE_MAP)
  uint occlusionTexture; // slot of the occlusion texture (with MATERIAL_OCCLUSION_MAP)
  uint pad;
};

TAA_BLOCK(TraceUniforms) {
  vec4 size;    // w, h, 1/w, 1/h
  vec4 params;  // x: gradient scale 2^lod_bias
  uvec4 roots;  // x: static BVH root, y: movers' root (TRACE_NO_ROOT when none)
  vec4 offsets[TRACE_MAX_SAMPLES];  // xy: sub-pixel sample positions, pixels from the centre
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
static_assert(sizeof(BvhNode) == 32);
static_assert(sizeof(TraceTriangle) == 48);
static_assert(sizeof(TraceShading) == 160);
static_assert(sizeof(TraceMaterial) == 64);
static_assert(sizeof(TraceUniforms) == 48 + 16 * TRACE_MAX_SAMPLES);
static_assert(sizeof(SegmentationUniforms) == 64);
static_assert(sizeof(InjectPush) == 80);
static_assert(sizeof(PostPush) == 32);
static_assert(sizeof(StillPush) == 32);
static_assert(sizeof(TaaUniforms) == 2 * 64 + (5 + TAA_SETTING_VEC4S) * 16);
static_assert(sizeof(FrameUniforms) == (7 + SHADOW_MAX_CASCADES) * 64 + 11 * 16);
static_assert(sizeof(ShadowPush) == 96);
static_assert(sizeof(InstanceData) == 3 * 64 + 16);
static_assert(sizeof(DrawPush) == 64);
static_assert(sizeof(TscmaaUniforms) == 48);
static_assert(sizeof(EdgeListHeader) == 16);
}  // namespace taa::gpu
#endif
