#version 450
#extension GL_GOOGLE_include_directive : require
#include "common/frame.glsl"
#include "common/lighting.glsl"

layout(constant_id = GBUF_SPEC_DEFERRED) const bool kDeferred = false;

layout(set = 0, binding = GBUF_BINDING_TEXTURE) uniform sampler2D baseColorTexture;

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
  vec4 base = draw.baseColor * texture(baseColorTexture, inUv, draw.lodBias);
  // Only meshes with COLOR_0: an interpolated constant white is not exactly 1.
  if (instances[draw.instance].ids.w != 0u) base *= inColor;
  if (draw.alphaCutoff >= 0.0 && base.a < draw.alphaCutoff) discard;

  vec3 n = normalize(inNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided surfaces light their back face too

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
  vec3 shaded = shadeBlinnPhong(base.rgb, n, inWorldPos, frame);
  if (draw.emissive.rgb != vec3(0.0)) shaded += draw.emissive.rgb;
  outColor = kDeferred ? vec4(draw.emissive.rgb, 0.0) : vec4(shaded, base.a);
}
