#version 450
// Deferred path: shade each pixel from the G-buffer (albedo, normal, depth) with
// the same Blinn-Phong as forward shading; sky pixels (albedo alpha 0) emit albedo.
// gbuffer.frag left each surface's emission (KHR_materials_emissive_strength) in the
// colour target, which this pass reads before it overwrites it.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "common/lighting.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(std140, binding = 0) uniform FrameBlock { FrameUniforms frame; };
layout(binding = 1) uniform sampler2D albedoTex;
layout(binding = 2) uniform sampler2D normalTex;
layout(binding = 3) uniform sampler2D depthTex;
layout(binding = 4, rgba16f) uniform image2D colorOut;
#if defined(VARIANT_MASK) && (VARIANT_MASK & GBUF_OUTPUT_SHADOW) != 0
#include "common/shadow.glsl"
layout(binding = DEFERRED_BINDING_SHADOW) uniform sampler2DShadow shadowAtlas;
#endif

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(frame.renderSize.xy)))) return;
  vec4 albedo = texelFetch(albedoTex, p, 0);
  // Sky (alpha 0) and unlit surfaces (alpha < 0, KHR_materials_unlit) show their colour.
  if (albedo.a <= 0.0) {
    imageStore(colorOut, p, vec4(albedo.rgb, 1.0));
    return;
  }
  float occlusion = 2.0 - albedo.a;  // gbuffer.frag's encoding: 1 without an occlusion texture
  // Reconstruct the world position from the jittered depth sample: the pixel centre
  // shows the un-jittered position (centre - jitter).
  float depth = texelFetch(depthTex, p, 0).r;
  vec2 ndc = (vec2(p) + 0.5 - frame.jitter.xy) * frame.renderSize.zw * 2.0 - 1.0;
  vec4 world = frame.invViewProjNoJitter * vec4(ndc, depth, 1.0);
  vec3 n = normalize(texelFetch(normalTex, p, 0).xyz);
#if defined(VARIANT_MASK) && (VARIANT_MASK & GBUF_OUTPUT_SHADOW) != 0
  vec3 pos = world.xyz / world.w;
  float visibility = shadowVisibility(shadowAtlas, frame, pos, n);
  vec3 c = occlusion != 1.0 ? shadeBlinnPhongOccluded(albedo.rgb, n, pos, frame, visibility, occlusion)
                            : shadeBlinnPhongShadowed(albedo.rgb, n, pos, frame, visibility);
#else
  vec3 c = occlusion != 1.0 ? shadeBlinnPhongOccluded(albedo.rgb, n, world.xyz / world.w, frame, 1.0, occlusion)
                            : shadeBlinnPhong(albedo.rgb, n, world.xyz / world.w, frame);
#endif
  vec3 emitted = imageLoad(colorOut, p).rgb;
  if (emitted != vec3(0.0)) c += emitted;
  imageStore(colorOut, p, vec4(c, 1.0));
}
