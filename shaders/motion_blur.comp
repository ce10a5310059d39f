#version 450
// Motion blur before the resolve: each pixel averages taps of the current colour
// along its own velocity (a box filter over the exposure, centred on the pixel,
// spanning velocity * scale). Gathering along the pixel's own motion is the cheap
// form of the effect: a moving object smears within its silhouette, and static
// pixels are copied untouched.
//
// Depth-aware weighting: a tap whose surface is more than params.y (relative, in
// reversed-Z) nearer than the centre is an occluder in front of it, not part of
// the surface that moved across this pixel; it gets weight 0 so slow background
// does not pick up the colour of fast foreground next to it. Non-finite taps get
// weight 0 too.
//
// With velocity in alpha, alpha holds the pixel's speed in render pixels (the
// unscaled velocity length) for the resolve's velocity-driven alpha; otherwise 1.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "post/post_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = MB_SPEC_SAMPLES) const int kSamples = 8;
layout(constant_id = MB_SPEC_VELOCITY_IN_ALPHA) const bool kVelocityInAlpha = false;

layout(push_constant) uniform Push { PostPush pc; };
layout(binding = MB_BINDING_COLOR) uniform sampler2D colorTex;
layout(binding = MB_BINDING_VELOCITY) uniform sampler2D velocityTex;
layout(binding = MB_BINDING_DEPTH) uniform sampler2D depthTex;
layout(binding = MB_BINDING_OUT, rgba16f) uniform writeonly image2D outImage;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(pc.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  ivec2 hi = size - 1;

  vec3 centre = texelFetch(colorTex, p, 0).rgb;
  vec2 velocity = texelFetch(velocityTex, p, 0).xy;
  // A broken motion vector must not scatter the blur across the screen.
  if (any(isnan(velocity)) || any(isinf(velocity))) velocity = vec2(0.0);
  float alpha = kVelocityInAlpha ? length(velocity) : 1.0;
  vec2 span = velocity * pc.params.x;
  if (span == vec2(0.0)) {  // static: the input, bit for bit
    imageStore(outImage, p, vec4(centre, alpha));
    return;
  }

  float centreDepth = texelFetch(depthTex, p, 0).r;
  float nearLimit = centreDepth * (1.0 + pc.params.y) + 1e-7;
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int i = 0; i < kSamples; ++i) {
    float t = float(i) / float(kSamples - 1) - 0.5;
    ivec2 q = clamp(ivec2(floor(vec2(p) + 0.5 + span * t)), ivec2(0), hi);
    vec3 c = texelFetch(colorTex, q, 0).rgb;
    float w = isFinite3(c) && texelFetch(depthTex, q, 0).r <= nearLimit ? 1.0 : 0.0;
    sum += w > 0.0 ? c : vec3(0.0);  // 0 * NaN is NaN: select, do not multiply
    weight += w;
  }
  vec3 result = weight > 0.0 ? sum / weight : scrub(centre);
  imageStore(outImage, p, vec4(min(result, vec3(kHalfMax)), alpha));
}
