#version 450
// Contrast Adaptive Sharpening, after AMD FidelityFX CAS (Lottes): a 5-tap cross
// filter whose negative lobe adapts per pixel and channel to the headroom left in
// the 3x3 neighbourhood, so already-contrasty pixels are sharpened less and nothing
// is pushed past the local extremes.
//  - soft limits: the min (max) of the cross plus the min (max) of the full 3x3,
//    i.e. twice a softened extreme in [0, 2];
//  - amplitude: sqrt(saturate(min(softMin, 2 - softMax) / softMax)), the distance to
//    the nearer signal limit relative to the local maximum;
//  - lobe weight: amplitude * peak, peak = -1 / mix(8, 5, sharpness) (-1/8 .. -1/5);
//  - out = (w * (n + s + e + w) + c) / (1 + 4w).
// CAS is defined on [0,1] signals, so HDR colour goes through c / (1 + c) and back.
// The result is clamped to the pixel's 3x3 min/max in both spaces (the inverse
// tonemap's rounding must not step outside), and a channel CAS leaves unchanged is
// copied from the input so flat regions stay bit-exact.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "post/post_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(push_constant) uniform Push { PostPush pc; };
layout(binding = POST_BINDING_INPUT) uniform sampler2D inputTex;
layout(binding = POST_BINDING_OUTPUT, rgba16f) uniform writeonly image2D outImage;

vec3 tap(ivec2 q, ivec2 hi) { return scrub(texelFetch(inputTex, clamp(q, ivec2(0), hi), 0).rgb); }

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(pc.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  ivec2 hi = size - 1;
  float centreAlpha = texelFetch(inputTex, p, 0).a;

  // a b c
  // d e f
  // g h i
  vec3 a = tap(p + ivec2(-1, -1), hi), b = tap(p + ivec2(0, -1), hi), c = tap(p + ivec2(1, -1), hi);
  vec3 d = tap(p + ivec2(-1, 0), hi), e = tap(p, hi), f = tap(p + ivec2(1, 0), hi);
  vec3 g = tap(p + ivec2(-1, 1), hi), h = tap(p + ivec2(0, 1), hi), i = tap(p + ivec2(1, 1), hi);

  vec3 crossMin = min(min(min(b, d), min(f, h)), e);
  vec3 crossMax = max(max(max(b, d), max(f, h)), e);
  vec3 boxMin = min(crossMin, min(min(a, c), min(g, i)));
  vec3 boxMax = max(crossMax, max(max(a, c), max(g, i)));

  // The tonemap is monotonic per channel: extremes map to extremes.
  vec3 tBoxMin = tonemap(boxMin), tBoxMax = tonemap(boxMax);
  vec3 softMin = tonemap(crossMin) + tBoxMin;
  vec3 softMax = tonemap(crossMax) + tBoxMax;
  // A black neighbourhood has no headroom to measure; the floor keeps 0/0 out.
  vec3 amplitude = sqrt(clamp(min(softMin, 2.0 - softMax) / max(softMax, vec3(1e-6)), 0.0, 1.0));
  vec3 lobe = amplitude * pc.params.x;

  vec3 te = tonemap(e);
  vec3 crossSum = tonemap(b) + tonemap(d) + tonemap(f) + tonemap(h);
  vec3 t = clamp((lobe * crossSum + te) / (1.0 + 4.0 * lobe), tBoxMin, tBoxMax);
  vec3 result = clamp(untonemap(t), boxMin, boxMax);
  result = mix(result, e, equal(t, te));
  imageStore(outImage, p, vec4(result, centreAlpha));
}
