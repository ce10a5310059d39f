#version 450
// TSCMAA step 3: TAA on the TAA share of the edge pixels (indirect dispatch over the TAA
// list). The CMAA pixel is blended with the eye's history, reprojected by depth and
// resampled with the 5-tap Catmull-Rom, after variance clipping in YCoCg against the
// CMAA image's 3x3 neighbourhood. Every other pixel of the new history was copied from
// the CMAA image: the output is CMAA everywhere but here, and becomes the next history.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "tscmaa/edge_rules.glsl"

layout(local_size_x = TSCMAA_LIST_GROUP) in;

// The resolve's includes, fixed to TSCMAA's choices: linear blend, YCoCg variance box,
// clip, Catmull-Rom 5-tap, depth reprojection.
const int kToneWeight = 0;
const bool kYCoCg = true;
const bool kShaped = false;
const bool kVarianceClip = true;
const bool kShrinkChroma = false;
const int kRectify = 2;
const int kHistoryFilter = 3;
const int kUseVelocity = 0;
const int kVelocitySampling = 0;

layout(std140, binding = TSCMAA_BINDING_UNIFORMS) uniform TscmaaBlock { TscmaaUniforms u; };
layout(std140, binding = TSCMAA_BINDING_TAA_UNIFORMS) uniform TaaBlock { TaaUniforms taaUniforms; };
layout(std430, binding = TSCMAA_BINDING_TAA_LIST) readonly buffer TaaList {
  EdgeListHeader taaHeader;
  uint taaEntries[];
};
layout(binding = TSCMAA_BINDING_CMAA) uniform sampler2D cmaaTex;
layout(binding = TSCMAA_BINDING_DEPTH) uniform sampler2D depthTex;
layout(binding = TSCMAA_BINDING_HISTORY) uniform sampler2D historyTex;
layout(binding = TSCMAA_BINDING_HISTORY_OUT, rgba16f) uniform writeonly image2D historyOut;
// Named by reprojection.glsl's velocity paths, which the constants above compile out.
layout(binding = TSCMAA_BINDING_COUNT) uniform sampler2D velocityTex;
layout(binding = TSCMAA_BINDING_COUNT + 1) uniform usampler2D idsTex;

#include "taa/color_space.glsl"
#include "taa/history_filter.glsl"
#include "taa/neighborhood.glsl"
#include "taa/rectify.glsl"
#include "taa/reprojection.glsl"

bool offscreen(vec2 uv) { return any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))); }

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= taaHeader.count) return;
  ivec2 p = unpackPixel(taaEntries[index]);
  ivec2 hi = ivec2(u.size.xy) - 1;
  ivec2 offset = ivec2(int(u.eye.x), 0);

  vec3 taps[9];
  bool valid[9];
  vec3 current = vec3(0.0);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      int k = (j + 1) * 3 + (i + 1);
      vec3 c = texelFetch(cmaaTex, clamp(p + ivec2(i, j), ivec2(0), hi) + offset, 0).rgb;
      valid[k] = !any(isnan(c));
      c = boundColor(c);
      taps[k] = toWorking(c);
      if (k == 4) current = c;
    }

  vec2 uv = (vec2(p) + 0.5) * u.size.zw;
  Reprojection r = reprojectDepth(uv, texelFetch(depthTex, p, 0).r);
  vec3 result = current;
  if (!offscreen(r.prevUv)) {
    vec3 history = max(historyCatmullRom5(historyTex, r.prevUv, taaUniforms.outputSize), vec3(0.0));
    Box box = neighborhoodBox(taps, valid, toWorking(current));
    vec3 rectified = fromWorking(rectifyHistory(toWorking(history), box));
    result = mix(rectified, current, taaUniforms.blend.x);
  }
  imageStore(historyOut, p, vec4(roundToHalf(boundColor(result)), 1.0));  // RGBA16F history
}
