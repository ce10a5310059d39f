#version 450
#extension GL_GOOGLE_include_directive : require
#include "common/frame.glsl"
#include "common/sky.glsl"

layout(constant_id = GBUF_SPEC_DEFERRED) const bool kDeferred = false;

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
  // The fragment at pixel centre c shows the un-jittered position c - jitter.
  vec2 pixel = gl_FragCoord.xy - frame.jitter.xy;
  vec2 ndc = pixel * frame.renderSize.zw * 2.0 - 1.0;
  vec4 far = frame.skyInvViewProj * vec4(ndc, 0.5, 1.0);
  vec3 dir = normalize(far.xyz / far.w);
  vec3 c = skyColor(dir);
  outColor = kDeferred ? vec4(0.0) : vec4(c, 1.0);
#if (VARIANT_MASK & GBUF_OUTPUT_VELOCITY) != 0
  // Both ends projected the same way, so a camera that did not turn gives exactly 0.
  vec4 curClip = frame.skyViewProj * vec4(dir, 0.0);
  vec4 prevClip = frame.skyPrevViewProj * vec4(dir, 0.0);
  vec2 curPixel = (curClip.xy / curClip.w * 0.5 + 0.5) * frame.renderSize.xy;
  vec2 prevPixel = (prevClip.xy / prevClip.w * 0.5 + 0.5) * frame.renderSize.xy;
  // A direction behind last frame's camera has no previous pixel: report no motion
  // rather than a mirrored one; TAA rejects such history through its other checks.
  outVelocity = prevClip.w > 0.0 ? curPixel - prevPixel : vec2(0.0);
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_ALBEDO) != 0
  outAlbedo = vec4(c, 0.0);  // alpha 0 marks sky for the deferred pass: emit, do not shade
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_NORMAL) != 0
  outNormal = vec4(0.0);
#endif
#if (VARIANT_MASK & GBUF_OUTPUT_IDS) != 0
  outIds = IDS_SKY;
#endif
}
