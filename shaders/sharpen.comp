#version 450
// Simple 5-tap gradient sharpener: adds amount times the discrete Laplacian
// (centre minus the mean of its 4 edge neighbours) back to the centre,
//   out = c + amount * (4c - n - s - e - w) / 4,
// so a flat region is left exactly as it is and an edge's two sides are pushed
// apart. Linear HDR, clamped to [0, half max]: undershoot below black has no meaning.
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
  vec4 centre = texelFetch(inputTex, p, 0);
  vec3 c = scrub(centre.rgb);
  vec3 laplacian = 4.0 * c - tap(p + ivec2(0, -1), hi) - tap(p + ivec2(0, 1), hi) -
                   tap(p + ivec2(1, 0), hi) - tap(p + ivec2(-1, 0), hi);
  vec3 result = c + pc.params.x * 0.25 * laplacian;
  imageStore(outImage, p, vec4(clamp(result, vec3(0.0), vec3(kHalfMax)), centre.a));
}
