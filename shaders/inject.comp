#version 450
// Writes a non-finite value into chosen pixels of the rendered colour (stress cases).
// The value is built from bits at run time so no compiler folds it away.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 1) in;
layout(binding = 0, rgba16f) uniform image2D color;
layout(push_constant) uniform Push { InjectPush inject; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (float(i) >= inject.params.x) return;
  vec4 pair = inject.pixels[i / 2u];
  ivec2 p = ivec2((i % 2u) == 0u ? pair.xy : pair.zw);
  uint kind = uint(inject.params.y);
  float v = kind == uint(INJECT_NAN)       ? uintBitsToFloat(0x7fc00000u)
            : kind == uint(INJECT_POS_INF) ? uintBitsToFloat(0x7f800000u)
                                           : uintBitsToFloat(0xff800000u);
  imageStore(color, p, vec4(v, v, v, 1.0));
}
