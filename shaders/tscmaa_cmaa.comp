#version 450
// TSCMAA step 2: conservative morphological AA on the edge pixels only, one list entry
// per invocation (indirect dispatch sized by the edge pass). Each invocation writes its
// own pixel from reads of the unmodified colour and the mask, so the result does not
// depend on the list's order. The other pixels were copied from the colour beforehand.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "tscmaa/edge_rules.glsl"

layout(local_size_x = TSCMAA_LIST_GROUP) in;

layout(std140, binding = TSCMAA_BINDING_UNIFORMS) uniform TscmaaBlock { TscmaaUniforms u; };
layout(binding = TSCMAA_BINDING_COLOR) uniform sampler2D colorTex;
layout(binding = TSCMAA_BINDING_MASK, r32ui) uniform readonly uimage2D maskIn;
layout(std430, binding = TSCMAA_BINDING_EDGE_LIST) readonly buffer EdgeList {
  EdgeListHeader edgeHeader;
  uint edgeEntries[];
};
layout(binding = TSCMAA_BINDING_CMAA, rgba16f) uniform writeonly image2D cmaaOut;

ivec2 gSize;

bool inEye(ivec2 q) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, gSize)); }

uint maskAt(ivec2 q) {
  if (!inEye(q)) return 0u;
  return imageLoad(maskIn, q + ivec2(int(u.eye.x), 0)).r & TSCMAA_EDGES;
}

// Colours are scrubbed (NaN -> 0, then [0, half max]) so one broken pixel cannot spread.
vec3 colorAt(ivec2 q) {
  vec3 c = texelFetch(colorTex, q, 0).rgb;
  return clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(65504.0));
}

#include "tscmaa/simple_shape.glsl"
#include "tscmaa/zshape.glsl"

const ivec2 kSides[4] = ivec2[](ivec2(-1, 0), ivec2(0, -1), ivec2(1, 0), ivec2(0, 1));

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= edgeHeader.count) return;
  ivec2 p = unpackPixel(edgeEntries[index]);
  gSize = ivec2(u.size.xy);
  uint edges = maskAt(p);
  vec3 centre = colorAt(p);
  float alpha = texelFetch(colorTex, p, 0).a;

  // Long edges first: coverage from every side that belongs to a Z shape.
  float share[4];
  float total = 0.0;
  for (int s = 0; s < 4; ++s) {
    share[s] = (edges & sideBit(kSides[s])) != 0u ? zCoverage(p, kSides[s]) : 0.0;
    total += share[s];
  }
  vec3 result = centre;
  if (total > 0.0) {
    // Shares from opposite sides of a thin feature may add up past 1: renormalise.
    float scale = total > 1.0 ? 1.0 / total : 1.0;
    result = centre * (1.0 - total * scale);
    for (int s = 0; s < 4; ++s) result += colorAt(p + kSides[s]) * (share[s] * scale);
  } else {
    float w = simpleShapeWeight(edges, u.params.z);
    if (w > 0.0) {
      vec3 sum = centre;
      float weight = 1.0;
      for (int s = 0; s < 4; ++s) {
        if ((edges & sideBit(kSides[s])) == 0u) continue;
        sum += colorAt(p + kSides[s]) * w;
        weight += w;
      }
      result = sum / weight;
    }
  }
  imageStore(cmaaOut, p + ivec2(int(u.eye.x), 0), vec4(result, alpha));
}
