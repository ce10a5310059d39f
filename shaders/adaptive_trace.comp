#version 450
// Adaptive ray tracing's trace pass: every pixel the segmentation marked gets
// kSamples primary rays at fixed stratified sub-pixel positions (un-jittered, like
// the resolve's output), traced through the CPU-built BVHs and shaded exactly as the
// raster pass shades (Blinn-Phong, base colour factor times the sRGB texture and the
// vertex colour, emission, alpha test, "over" blending, the same sky). Their average replaces the resolve's output
// at that pixel; since that image is the next frame's history, the traced result
// also feeds the history. Unmarked pixels are not touched.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "common/lighting.glsl"
#include "common/sky.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = TRACE_SPEC_SAMPLES) const int kSamples = 4;
layout(constant_id = TRACE_SPEC_RAY_LOD) const bool kRayLod = true;
layout(constant_id = TRACE_SPEC_ANISO) const float kAniso = 1.0;
layout(constant_id = TRACE_SPEC_LOD0_ALPHA) const bool kLod0Alpha = false;
layout(constant_id = TRACE_SPEC_TEXTURE_SLOTS) const int kTextureSlots = TRACE_MAX_TEXTURES;

layout(std140, binding = TRACE_BINDING_FRAME) uniform FrameBlock { FrameUniforms frame; };
layout(std140, binding = TRACE_BINDING_PARAMS) uniform TraceBlock { TraceUniforms trace; };
layout(std430, binding = TRACE_BINDING_NODES) readonly buffer Nodes { BvhNode nodes[]; };
layout(std430, binding = TRACE_BINDING_TRIANGLES) readonly buffer T { TraceTriangle triangles[]; };
layout(std430, binding = TRACE_BINDING_SHADING) readonly buffer Shading { TraceShading shading[]; };
layout(std430, binding = TRACE_BINDING_MATERIALS) readonly buffer M { TraceMaterial materials[]; };
layout(binding = TRACE_BINDING_MASK) uniform usampler2D maskTex;
layout(binding = TRACE_BINDING_OUT) uniform writeonly image2D outImage;
layout(binding = TRACE_BINDING_TEXTURES) uniform sampler2D textures[TRACE_MAX_TEXTURES];

#include "trace/bvh.glsl"
#include "trace/surface.glsl"

// Surfaces a ray passes through (alpha-tested texels, blended layers) before it
// stops counting them; the rest of its weight goes to the sky.
const int kMaxLayers = 16;

vec3 unproject(vec2 pixel, float depth) {
  vec2 ndc = pixel * trace.size.zw * 2.0 - 1.0;
  vec4 w = frame.invViewProjNoJitter * vec4(ndc, depth, 1.0);
  return w.xyz / w.w;
}

// Reversed Z: depth 1 is the near plane, 0 the far plane, so the ray covers exactly
// what the raster's depth range keeps.
CameraRay cameraRay(vec2 pixel) {
  CameraRay r;
  r.origin = unproject(pixel, 1.0);
  r.dir = unproject(pixel, 0.0) - r.origin;
  return r;
}

// lavapipe cannot index sampler arrays with a varying index (no
// shaderSampledImageArrayDynamicIndexing), so each slot is a case with a constant one.
// llvmpipe runs every case of a divergent switch under a lane mask, so each case costs
// every ray its lookup: the cases past the scene's slot count (kTextureSlots) are compiled
// out (adaptive_mask_debug's trace pass took 111 ms a frame with all 16, 39 ms with 2).
// textureGrad has no bias argument; scaling the gradients by 2^bias adds bias to the LOD.
// adaptive.aniso: shortens the longer gradient (measured in texels) by up to kAniso, so
// the sampler's isotropic LOD follows the footprint's shorter axis; passes/adaptive/
// ray_differentials.cpp mirrors it (anisotropicGradients).
void anisotropicGradients(inout vec2 dx, inout vec2 dy, vec2 texels) {
  float lx = length(dx * texels), ly = length(dy * texels);
  // At least 1: a zero footprint (a triangle of one UV) has nothing to shorten, where 0 / 0
  // made NaN gradients.
  float ratio = max(min(max(lx, ly) / max(min(lx, ly), 1e-30), kAniso), 1.0);
  if (lx >= ly)
    dx /= ratio;
  else
    dy /= ratio;
}

// Every slot of `textures` as a case running LOOKUP(i), for both lookups below; a case past
// the scene's slot count is compiled out (the guard written once, here).
#define TRACE_TEXTURE_SLOT(LOOKUP, i) \
  case i:                             \
    if (i >= kTextureSlots) break;    \
    LOOKUP(i)
#define TRACE_TEXTURE_SLOTS(LOOKUP)                                                            \
  TRACE_TEXTURE_SLOT(LOOKUP, 0) TRACE_TEXTURE_SLOT(LOOKUP, 1) TRACE_TEXTURE_SLOT(LOOKUP, 2)    \
  TRACE_TEXTURE_SLOT(LOOKUP, 3) TRACE_TEXTURE_SLOT(LOOKUP, 4) TRACE_TEXTURE_SLOT(LOOKUP, 5)    \
  TRACE_TEXTURE_SLOT(LOOKUP, 6) TRACE_TEXTURE_SLOT(LOOKUP, 7) TRACE_TEXTURE_SLOT(LOOKUP, 8)    \
  TRACE_TEXTURE_SLOT(LOOKUP, 9) TRACE_TEXTURE_SLOT(LOOKUP, 10) TRACE_TEXTURE_SLOT(LOOKUP, 11)  \
  TRACE_TEXTURE_SLOT(LOOKUP, 12) TRACE_TEXTURE_SLOT(LOOKUP, 13) TRACE_TEXTURE_SLOT(LOOKUP, 14) \
  TRACE_TEXTURE_SLOT(LOOKUP, 15)
#define TRACE_TEXTURE_LOOKUP(i)                                                                \
  {                                                                                            \
    vec2 gx = dx * trace.params.x, gy = dy * trace.params.x;                                   \
    if (kAniso > 1.0) anisotropicGradients(gx, gy, vec2(textureSize(textures[i], 0)));         \
    return kRayLod ? textureGrad(textures[i], uv, gx, gy) : textureLod(textures[i], uv, 0.0);  \
  }
#define TRACE_TEXTURE_LOD0_LOOKUP(i) return textureLod(textures[i], uv, 0.0);

vec4 sampleTexture(uint slot, vec2 uv, vec2 dx, vec2 dy) {
  switch (slot) { TRACE_TEXTURE_SLOTS(TRACE_TEXTURE_LOOKUP) }
  return vec4(1.0);
}

vec4 sampleTextureLod0(uint slot, vec2 uv) {
  switch (slot) { TRACE_TEXTURE_SLOTS(TRACE_TEXTURE_LOD0_LOOKUP) }
  return vec4(1.0);
}

// A map's lookup on the UV set its MATERIAL_*_UV1 bit names.
vec4 sampleMap(TraceMaterial m, uint slot, uint uv1Bit, Surface s) {
  return (m.maps & uv1Bit) != 0u ? sampleTexture(slot, s.uv1, s.dUv1Dx, s.dUv1Dy)
                                 : sampleTexture(slot, s.uv, s.dUvDx, s.dUvDy);
}

vec2 baseUv(TraceMaterial m, Surface s) { return (m.maps & MATERIAL_BASE_UV1) != 0u ? s.uv1 : s.uv; }

vec4 baseColor(TraceMaterial m, Surface s, uint tri) {
  vec4 base = m.baseColor * sampleMap(m, m.texture, MATERIAL_BASE_UV1, s);
  // As the raster: only meshes with COLOR_0 (an interpolated white is not exactly 1).
  if (shading[tri].uv2.z != 0.0) base *= s.color;
  return base;
}

vec3 traceSample(vec2 pixel) {
  CameraRay r = cameraRay(pixel);
  CameraRay rx = cameraRay(pixel + vec2(1.0, 0.0));
  CameraRay ry = cameraRay(pixel + vec2(0.0, 1.0));
  vec3 sum = vec3(0.0);
  float transmit = 1.0;
  float afterT = -1.0;
  uint afterTri = 0u;
  for (int layer = 0; layer < kMaxLayers; ++layer) {
    Hit h = closestHit(r.origin, r.dir, 1.0, afterT, afterTri);
    if (h.tri == TRACE_NO_ROOT) break;
    afterT = h.t;
    afterTri = h.tri;
    TraceMaterial m = materials[triangles[h.tri].material];
    Surface s = surfaceAt(h, r, rx, ry);
    if (m.doubleSided == 0u && !s.front) continue;  // the raster culls it: the ray passes
    vec4 base = baseColor(m, s, h.tri);
    float testedAlpha = base.a;
    if (kLod0Alpha && m.alphaCutoff >= 0.0)  // render.lod0_alpha_test, as the raster
      testedAlpha = m.baseColor.a * sampleTextureLod0(m.texture, baseUv(m, s)).a * (shading[h.tri].uv2.z != 0.0 ? s.color.a : 1.0);
    if (m.alphaCutoff >= 0.0 && testedAlpha < m.alphaCutoff) continue;  // the raster's discard
    vec3 c;
    if ((m.maps & MATERIAL_UNLIT) != 0u) {
      c = base.rgb;  // KHR_materials_unlit, as gbuffer.frag
    } else {
      float occlusion = 1.0;
      if ((m.maps & MATERIAL_OCCLUSION_MAP) != 0u)
        occlusion = occlusionFactor(sampleMap(m, m.occlusionTexture, MATERIAL_OCCLUSION_UV1, s).r, m.emissive.w);
      c = occlusion != 1.0 ? shadeBlinnPhongOccluded(base.rgb, s.normal, s.position, frame, 1.0, occlusion)
                           : shadeBlinnPhong(base.rgb, s.normal, s.position, frame);
      vec3 emission = m.emissive.rgb;
      if ((m.maps & MATERIAL_EMISSIVE_MAP) != 0u)
        emission *= sampleMap(m, m.emissiveTexture, MATERIAL_EMISSIVE_UV1, s).rgb;
      if (emission != vec3(0.0)) c += emission;
    }
    if (m.blend == 0u) return sum + transmit * c;
    sum += transmit * base.a * c;
    transmit *= 1.0 - base.a;
  }
  return sum + transmit * skyColor(normalize(r.dir));
}

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, ivec2(trace.size.xy)))) return;
  uint mark = texelFetch(maskTex, q, 0).r;
  if (mark != ADAPTIVE_MASK_TRACE && mark != ADAPTIVE_MASK_TRACE_HISTORY) return;
  vec3 sum = vec3(0.0);
  for (int i = 0; i < kSamples; ++i) sum += traceSample(vec2(q) + 0.5 + trace.offsets[i].xy);
  imageStore(outImage, q, vec4(sum / float(kSamples), 1.0));
}
