#version 450
// Still-image upsampling (debug.image, the seed's Debug/image mode): the image stands in
// for the rendered scene. Each render pixel shows the image at its jittered centre, as a
// rasteriser samples geometry there, so TAA (render.upsample) can rebuild the full-size
// image from the low-resolution frames. The sampler decides bilinear or nearest.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = STILL_BINDING_IMAGE) uniform sampler2D still;
layout(binding = STILL_BINDING_OUT, rgba16f) uniform writeonly image2D colorOut;
layout(push_constant) uniform PushBlock { StillPush push; };

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(push.size.xy)))) return;
  // The image moves by the jitter, so this pixel sees the point at its centre minus it.
  vec2 uv = (vec2(p) + 0.5 - push.jitter.xy) * push.size.zw;
  imageStore(colorOut, p, vec4(texture(still, uv).rgb, 1.0));
}
