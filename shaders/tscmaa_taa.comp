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

#include "taa/settings.glsl"

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

#include "taa/color_space.glsl"
#include "taa/history_filter.glsl"
#include "taa/neighborhood.glsl"
#include "taa/rectify.glsl"
#include "taa/reprojection.glsl"
#include "taa/validation.glsl"

// The resolve's techniques, fixed to TSCMAA's choices: linear blend, YCoCg variance box
// (gamma from the uniforms), clip, Catmull-Rom 5-tap, depth reprojection.
TaaSettings tscmaaSettings() {
  TaaSettings s = taaDefaultSettings();
  s.alpha = TAA_SETTING(taaUniforms, TAA_PARAM_ALPHA);
  s.variance_gamma = TAA_SETTING(taaUniforms, TAA_PARAM_VARIANCE_GAMMA);
  s.tonemap_weighting = TONE_WEIGHT_NONE;
  s.color_space = COLOR_SPACE_YCOCG;
  s.shaped_neighborhood = false;
  s.variance_clip = true;
  s.shrink_chroma = false;
  s.rectify = RECTIFY_CLIP;
  s.history_filter = HISTORY_FILTER_CATMULL_ROM_5;
  s.use_velocity = USE_VELOCITY_OFF;
  return s;
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= taaHeader.count) return;
  ivec2 p = unpackPixel(taaEntries[index]);
  ivec2 hi = ivec2(u.size.xy) - 1;
  ivec2 offset = ivec2(int(u.eye.x), 0);
  TaaSettings s = tscmaaSettings();

  vec3 taps[9];
  bool valid[9];
  vec3 current = vec3(0.0);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      int k = (j + 1) * 3 + (i + 1);
      vec3 c = texelFetch(cmaaTex, clamp(p + ivec2(i, j), ivec2(0), hi) + offset, 0).rgb;
      valid[k] = !any(isnan(c));
      c = boundColor(c);
      taps[k] = toWorking(s, c);
      if (k == 4) current = c;
    }

  vec2 uv = (vec2(p) + 0.5) * u.size.zw;
  Reprojection r = reprojectDepth(taaUniforms, uv, texelFetch(depthTex, p, 0).r);
  vec3 result = current;
  if (!offscreen(r.prevUv)) {
    vec3 history = sampleHistory(s, historyTex, r.prevUv, taaUniforms.outputSize);
    Box box = neighborhoodBox(s, taps, valid, toWorking(s, current), r.motionPx);
    vec3 rectified = fromWorking(s, rectifyHistory(s, toWorking(s, history), box));
    result = mix(rectified, current, s.alpha);
  }
  imageStore(historyOut, p, vec4(roundToHalf(boundColor(result)), 1.0));  // RGBA16F history
}
