#version 450
// debug.channels (the seed's R, G, B, A toggles): keeps the debug view's chosen channels
// and zeroes the rest (alpha reads 1 when hidden, so the view stays opaque).
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(push_constant) uniform Push { PostPush pc; };  // params: 1 per shown channel, r g b a
layout(binding = POST_BINDING_INPUT) uniform sampler2D inputTex;
layout(binding = POST_BINDING_OUTPUT, rgba16f) uniform writeonly image2D outImage;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(pc.size.xy)))) return;
  vec4 c = texelFetch(inputTex, p, 0);
  vec4 shown = vec4(mix(vec3(0.0), c.rgb, greaterThan(pc.params.rgb, vec3(0.5))), pc.params.a > 0.5 ? c.a : 1.0);
  imageStore(outImage, p, shown);
}
