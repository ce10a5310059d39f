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

void main() {
  // Normal-mapped materials only (a push constant, so uniform control flow): derivatives
  // taken before any discard, while the whole quad still runs.
  vec3 dpdx = vec3(0.0), dpdy = vec3(0.0), mapped = vec3(0.5, 0.5, 1.0);
  vec2 duvdx = vec2(0.0), duvdy = vec2(0.0);
  if (draw.emissive.w != 0.0) {
    dpdx = dFdx(inWorldPos);
    dpdy = dFdy(inWorldPos);
    duvdx = dFdx(inUv);
    duvdy = dFdy(inUv);
    mapped = kLod0 ? textureLod(normalTexture, inUv, 0.0).rgb : texture(normalTexture, inUv, draw.lodBias).rgb;
  }
  vec4 base = draw.baseColor *
              (kLod0 ? textureLod(baseColorTexture, inUv, 0.0) : texture(baseColorTexture, inUv, draw.lodBias));
  // Only meshes with COLOR_0: an interpolated constant white is not exactly 1.
  bool vertexColors = instances[draw.instance].ids.w != 0u;
  if (vertexColors) base *= inColor;
  float testedAlpha = base.a;
  if (kLod0Alpha && draw.alphaCutoff >= 0.0)
    testedAlpha = draw.baseColor.a * textureLod(baseColorTexture, inUv, 0.0).a * (vertexColors ? inColor.a : 1.0);
  if (draw.alphaCutoff >= 0.0 && testedAlpha < draw.alphaCutoff) discard;

  vec3 n = normalize(inNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces light their back face too
  if (draw.emissive.w != 0.0) n = perturbNormal(n, dpdx, dpdy, duvdx, duvdy, mapped, draw.emissive.w);

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
  InstanceData inst = instances[draw.instance];
  outIds = (inst.ids.y != 0u ? IDS_MOVER_BIT : 0u) | ((inst.ids.x & 0x7fffu) << 16) | (draw.material & 0xffffu);
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_ALBEDO) != 0
  outAlbedo = vec4(base.rgb, 1.0);
#endif
  // Emission is added only where there is some, so every other pixel stays bit for bit
  // what it was. The deferred path leaves it in the colour target for the lighting pass.
#if (VARIANT_MASK & GBUF_OUTPUT_SHADOW) != 0
  vec3 shaded = kDeferred ? vec3(0.0)
                          : shadeBlinnPhongShadowed(base.rgb, n, inWorldPos, frame,
                                                    shadowVisibility(shadowAtlas, frame, inWorldPos, n));
#else
  vec3 shaded = shadeBlinnPhong(base.rgb, n, inWorldPos, frame);
#endif
  if (draw.emissive.rgb != vec3(0.0)) shaded += draw.emissive.rgb;
  outColor = kDeferred ? vec4(draw.emissive.rgb, 0.0) : vec4(shaded, base.a);
}
