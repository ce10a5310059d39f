#version 450
#extension GL_GOOGLE_include_directive : require
#include "common/frame.glsl"
#include "common/lighting.glsl"
#include "common/normal_map.glsl"

layout(constant_id = GBUF_SPEC_DEFERRED) const bool kDeferred = false;
layout(constant_id = GBUF_SPEC_LOD0) const bool kLod0 = false;
layout(constant_id = GBUF_SPEC_LOD0_ALPHA) const bool kLod0Alpha = false;

layout(set = 0, binding = GBUF_BINDING_TEXTURE) uniform sampler2D baseColorTexture;
layout(set = 0, binding = GBUF_BINDING_NORMAL_MAP) uniform sampler2D normalTexture;
layout(set = 0, binding = GBUF_BINDING_EMISSIVE_MAP) uniform sampler2D emissiveTexture;
layout(set = 0, binding = GBUF_BINDING_OCCLUSION_MAP) uniform sampler2D occlusionTexture;
#if (VARIANT_MASK & GBUF_OUTPUT_SHADOW) != 0
#include "common/shadow.glsl"
layout(set = 0, binding = GBUF_BINDING_SHADOW) uniform sampler2DShadow shadowAtlas;
#endif

layout(location = 0) in vec3 inWorldPos;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inCurClip;
layout(location = 4) in vec4 inPrevClip;
layout(location = 5) in vec4 inColor;  // glTF COLOR_0, white elsewhere
layout(location = 6) in vec2 inUv1;    // glTF TEXCOORD_1
layout(location = 7) flat in uint inInstance;

layout(location = GBUF_OUT_COLOR) out vec4 outColor;
#if (VARIANT_MASK & GBUF_OUTPUT_VELOCITY) != 0
layout(location = GBUF_OUT_VELOCITY) out vec2 outVelocity;
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_NORMAL) != 0
layout(location = GBUF_OUT_NORMAL) out vec4 outNormal;
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_IDS) != 0
layout(location = GBUF_OUT_IDS) out uint outIds;
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_ALBEDO) != 0
layout(location = GBUF_OUT_ALBEDO) out vec4 outAlbedo;
#endif

// The UV set a texture samples (MATERIAL_*_UV1 bits of the draw).
vec2 uvSet(uint bit) { return (draw.maps & bit) != 0u ? inUv1 : inUv; }

vec4 sampleMap(sampler2D t, vec2 uv) {
  return kLod0 ? textureLod(t, uv, 0.0) : texture(t, uv, draw.lodBias);
}

void main() {
  // Every lookup comes before the alpha test's discard, and only the material's own maps
  // are sampled (push constants, so uniform control flow): derivatives taken while the
  // whole quad still runs.
  vec3 dpdx = vec3(0.0), dpdy = vec3(0.0), mapped = vec3(0.5, 0.5, 1.0);
  vec2 duvdx = vec2(0.0), duvdy = vec2(0.0);
  if (draw.emissive.w != 0.0) {
    vec2 normalUv = uvSet(MATERIAL_NORMAL_UV1);
    dpdx = dFdx(inWorldPos);
    dpdy = dFdy(inWorldPos);
    duvdx = dFdx(normalUv);
    duvdy = dFdy(normalUv);
    mapped = sampleMap(normalTexture, normalUv).rgb;
  }
  vec3 emission = draw.emissive.rgb;
  if ((draw.maps & MATERIAL_EMISSIVE_MAP) != 0u)
    emission *= sampleMap(emissiveTexture, uvSet(MATERIAL_EMISSIVE_UV1)).rgb;
  float occlusion = 1.0;
  if ((draw.maps & MATERIAL_OCCLUSION_MAP) != 0u)
    occlusion = occlusionFactor(sampleMap(occlusionTexture, uvSet(MATERIAL_OCCLUSION_UV1)).r,
                                draw.occlusionStrength);
  vec2 baseUv = uvSet(MATERIAL_BASE_UV1);
  vec4 base = draw.baseColor * sampleMap(baseColorTexture, baseUv);
  // Only meshes with COLOR_0: an interpolated constant white is not exactly 1.
  bool vertexColors = instances[inInstance].ids.w != 0u;
  if (vertexColors) base *= inColor;
  float testedAlpha = base.a;
  if (kLod0Alpha && draw.alphaCutoff >= 0.0)
    testedAlpha = draw.baseColor.a * textureLod(baseColorTexture, baseUv, 0.0).a * (vertexColors ? inColor.a : 1.0);
  if (draw.alphaCutoff >= 0.0 && testedAlpha < draw.alphaCutoff) discard;

  bool unlit = (draw.maps & MATERIAL_UNLIT) != 0u;
  vec3 n = normalize(inNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces light their back face too
  if (draw.emissive.w != 0.0 && !unlit) n = perturbNormal(n, dpdx, dpdy, duvdx, duvdy, mapped, draw.emissive.w);

#if (VARIANT_MASK & GBUF_OUTPUT_VELOCITY) != 0
  // Screen motion in pixels from last frame to this one, both un-jittered:
  // history for this pixel lies at (pixel - velocity).
  vec2 cur = inCurClip.xy / inCurClip.w;
  vec2 prev = inPrevClip.xy / inPrevClip.w;
  outVelocity = (cur - prev) * 0.5 * frame.renderSize.xy;
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_NORMAL) != 0
  outNormal = vec4(n, 0.0);
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_IDS) != 0
  InstanceData inst = instances[inInstance];
  outIds = (inst.ids.y != 0u ? IDS_MOVER_BIT : 0u) | ((inst.ids.x & 0x7fffu) << 16) | (draw.material & 0xffffu);
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_ALBEDO) != 0
  // Alpha tells the deferred pass how to shade: 0 is the sky, negative unlit, and otherwise
  // 2 - occlusion (1 without an occlusion texture).
  outAlbedo = vec4(base.rgb, unlit ? -1.0 : 2.0 - occlusion);
#endif
  // Emission is added only where there is some, so every other pixel stays bit for bit
  // what it was. The deferred path leaves it in the colour target for the lighting pass.
  vec3 shaded;
  if (unlit) {
    shaded = base.rgb;
    emission = vec3(0.0);
  } else if (kDeferred) {
    shaded = vec3(0.0);
  } else {
#if (VARIANT_MASK & GBUF_OUTPUT_SHADOW) != 0
    float visibility = shadowVisibility(shadowAtlas, frame, inWorldPos, n);
    shaded = occlusion != 1.0 ? shadeBlinnPhongOccluded(base.rgb, n, inWorldPos, frame, visibility, occlusion)
                              : shadeBlinnPhongShadowed(base.rgb, n, inWorldPos, frame, visibility);
#else
    shaded = occlusion != 1.0 ? shadeBlinnPhongOccluded(base.rgb, n, inWorldPos, frame, 1.0, occlusion)
                              : shadeBlinnPhong(base.rgb, n, inWorldPos, frame);
#endif
  }
  if (emission != vec3(0.0)) shaded += emission;
  outColor = kDeferred ? vec4(emission, 0.0) : vec4(shaded, base.a);
}
