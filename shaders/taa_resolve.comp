#version 450
// The temporal resolve: one output pixel per invocation. Every technique is a
// specialization constant, so a case's pipeline contains only what it enables.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

#include "taa/settings.glsl"

// The resolve's own constants and every setting's, from common/taa_settings.h.
#define TAA_CONSTANT_OWN(id, type, name, def) layout(constant_id = id) const type name = def;
TAA_RESOLVE_CONSTANTS(TAA_CONSTANT_OWN)

#define TAA_CONSTANT_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) \
  layout(constant_id = id) const int name = def;
#define TAA_CONSTANT_B(key, def, id, name, modes, reads, rule, text, doc, impl) layout(constant_id = id) const bool name = def;
#define TAA_CONSTANT_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl)
TAA_SETTINGS(TAA_CONSTANT_E, TAA_CONSTANT_B, TAA_CONSTANT_F)

layout(std140, binding = TAA_BINDING_UNIFORMS) uniform TaaBlock { TaaUniforms taaUniforms; };
TAA_INPUT_SAMPLERS  // one per row of common/resolve_inputs.h: colorTex, depthTex, ...
layout(binding = TAA_BINDING_HISTORY_OUT) uniform writeonly image2D historyOut;
layout(binding = TAA_BINDING_DEBUG_OUT, rgba16f) uniform writeonly image2D debugOut;
layout(binding = TAA_BINDING_REJECT_OUT, r32ui) uniform writeonly uimage2D rejectOut;

// This frame's settings: the constants above and the float settings' uniform slots.
#define TAA_FILL_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) s.key = name;
#define TAA_FILL_B(key, def, id, name, modes, reads, rule, text, doc, impl) s.key = name;
#define TAA_FILL_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) s.key = TAA_SETTING(taaUniforms, slot);
TaaSettings resolveSettings() {
  TaaSettings s;
  TAA_SETTINGS(TAA_FILL_E, TAA_FILL_B, TAA_FILL_F)
  return s;
}

#include "taa/color_space.glsl"
#include "taa/history_filter.glsl"
#include "taa/neighborhood.glsl"
#include "taa/rectify.glsl"
#include "taa/reprojection.glsl"
#include "taa/validation.glsl"
#include "taa/consistency.glsl"
#include "taa/blend_weight.glsl"
#include "taa/unjitter.glsl"
#include "taa/output_noise.glsl"
#include "taa/rejection.glsl"

struct Current {
  ivec2 pixel;   // render pixel providing the sample
  vec3 color;    // finite, bounded
  float weight;  // 1, or the upsampling reconstruction weight
};

// Without upsampling the output pixel's own render pixel is its sample. When
// upsampling, the nearest jittered sample is taken and weighted by its distance
// (in output pixels) from the output pixel's centre, so over the jitter sequence
// every output pixel gathers close samples.
Current currentSample(ivec2 q, ivec2 hi) {
  Current c;
  if (!kUpsample) {
    c.pixel = q;
    c.weight = 1.0;
  } else {
    vec2 pos = (vec2(q) + 0.5) * taaUniforms.outputSize.zw * taaUniforms.renderSize.xy;
    c.pixel = clamp(ivec2(floor(pos + taaUniforms.jitter.xy)), ivec2(0), hi);
    vec2 d = (pos - (vec2(c.pixel) + 0.5 - taaUniforms.jitter.xy)) * taaUniforms.outputSize.xy * taaUniforms.renderSize.zw;
    c.weight = exp(-2.29 * dot(d, d));
  }
  c.color = texelFetch(colorTex, c.pixel, 0).rgb;
  return c;
}

#if TAA_VALUE_COUNT(TAA_HISTORY_FORMAT_VALUES) != 2
#error "writeOutput: a taa.history_format value without its branch"
#endif
#if TAA_VALUE_COUNT(TAA_DEBUG_OUTPUT_VALUES) != 5
#error "writeOutput: a debug.output value without its branch"
#endif
void writeOutput(TaaSettings s, ivec2 q, vec3 color, float rejected, float clampDistance, vec2 motionPx) {
  // The output is also the next frame's history, so the noise enters it (as the seed's
  // resolve, which adds it to the image it writes).
  if (s.noise) color += vec3(outputNoise(q, uint(taaUniforms.jitter.z), s.noise_amount));
  vec3 bounded = boundColor(color);
  // HISTORY_FORMAT_RGBA16F is rounded here (the driver may round toward zero); RGBA32F as is.
  imageStore(historyOut, q, vec4(s.history_format == HISTORY_FORMAT_RGBA16F ? roundToHalf(bounded) : bounded, 1.0));
  if (kDebug == DEBUG_OUTPUT_VELOCITY) imageStore(debugOut, q, vec4(motionPx * taaUniforms.view.z * 0.5 + 0.5, 0.0, 1.0));
  if (kDebug == DEBUG_OUTPUT_REJECTION) imageStore(debugOut, q, vec4(rejected, 0.0, 0.0, 1.0));
  if (kDebug == DEBUG_OUTPUT_CLAMP_DISTANCE) imageStore(debugOut, q, vec4(vec3(clampDistance * taaUniforms.view.z), 1.0));
  // DEBUG_OUTPUT_NONE, and DEBUG_OUTPUT_SEGMENTATION (the adaptive pass draws it): no view here.
}

#if TAA_VALUE_COUNT(TAA_RESOLVE_VALUES) != 3
#error "main: a resolve path without its branch"
#endif
void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, ivec2(taaUniforms.outputSize.xy)))) return;
  ivec2 hi = ivec2(taaUniforms.renderSize.xy) - 1;
  vec2 uv = (vec2(q) + 0.5) * taaUniforms.outputSize.zw;
  TaaSettings s = resolveSettings();

  if (kResolve == RESOLVE_PASS_THROUGH) {  // pass-through: the input, bit for bit
    imageStore(historyOut, q, texelFetch(colorTex, min(q, hi), 0));
    return;
  }

  // Gather the 3x3 neighbourhood; non-finite samples neither shape the box nor
  // reach the history (a NaN or Inf stays confined to its own pixel and frame).
  Current cur = currentSample(q, hi);
  vec3 taps[9];
  bool valid[9];
  vec3 finiteSum = vec3(0.0), centre = vec3(0.0);
  float finiteCount = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      int k = (j + 1) * 3 + (i + 1);
      ivec2 tp = clamp(cur.pixel + ivec2(i, j), ivec2(0), hi);
      // The centre tap is the current sample the blend takes (and the box contains); the
      // eight around it are the neighbourhood. Unjittered, each is the colour at its pixel's
      // centre instead of its jittered sample.
      bool unjittered = k == 4 ? s.unjitter_current : s.unjitter_neighborhood;
      vec3 c = unjittered ? unjitteredColor(colorTex, tp, taaUniforms.jitter.xy, hi) : texelFetch(colorTex, tp, 0).rgb;
      valid[k] = !any(isnan(c));
      c = clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(kHalfMax));  // +Inf -> half max
      taps[k] = toWorking(s, c);
      if (k == 4) centre = c;
      if (valid[k]) {
        finiteSum += c;
        finiteCount += 1.0;
      }
    }
  vec3 current = valid[4] ? centre : (finiteCount > 0.0 ? finiteSum / finiteCount : vec3(0.0));

  if (!kHasHistory) {
    writeOutput(s, q, current, 1.0, 0.0, vec2(0.0));
    if (kRejectMask) imageStore(rejectOut, q, uvec4(TAA_REJECT_NO_HISTORY));
    return;
  }

  if (kResolve == RESOLVE_BASIC) {  // the same pixel last frame, no reprojection, no rejection
    vec3 h = texelFetch(historyTex, q, 0).rgb;
    writeOutput(s, q, toneWeightedBlend(s, h, current, s.alpha * cur.weight), 0.0, 0.0, vec2(0.0));
    return;
  }

  // RESOLVE_FULL from here on.
  // With the speed in alpha the resolve reads colour only (seed 001): last frame's colour
  // at the same pixel, its weight set by the speed motion blur packed into alpha (render
  // pixels, here scaled to output pixels). Validation refuses what would need depth.
  Reprojection r;
  float alphaSpeed = 0.0;
  if (s.velocity_in_alpha) {
    r.prevUv = uv;
    r.expectedDepth = 0.0;
    r.motionPx = vec2(0.0);
    alphaSpeed = texelFetch(colorTex, cur.pixel, 0).a * taaUniforms.outputSize.x * taaUniforms.renderSize.z;
  } else {
    r = reproject(s, taaUniforms, depthTex, velocityTex, idsTex, uv, cur.pixel, hi);
  }
  float speed = s.velocity_in_alpha ? alphaSpeed : length(r.motionPx);
  HistoryVerdict v = historyVerdict(s, taaUniforms TAA_INPUT_ARGS, r, uv, cur.pixel, hi);
  bool rejected = v.reason != TAA_REJECT_NONE;
  vec3 history = v.color;

  vec3 wHistory = toWorking(s, history);
  // The box reads only the motion's length, which is all the speed in alpha gives.
  Box box = neighborhoodBox(s, taps, valid, toWorking(s, current), s.velocity_in_alpha ? vec2(speed, 0.0) : r.motionPx);
  vec3 wRectified = rectifyHistory(s, wHistory, box);
  float clampDistance = abs(workingLuma(s, wRectified) - workingLuma(s, wHistory));

  float alpha = s.alpha;
  if (s.luma_weight) alpha = lottesAlpha(s, luma(current), luma(fromWorking(s, wRectified)));
  if (s.reduce_blend_near_clamp)
    alpha = reduceBlendNearClamp(alpha, workingLuma(s, wHistory), workingLuma(s, box.lo), workingLuma(s, box.hi));
  if (s.velocity_alpha) alpha = velocityAlpha(s, alpha, speed);
  if (s.velocity_attenuation) alpha = velocityAttenuation(alpha, speed);
  alpha *= cur.weight;
  if (rejected) alpha = s.rejection_alpha;

  vec3 result = toneWeightedBlend(s, fromWorking(s, wRectified), current, alpha);
  writeOutput(s, q, result, rejected ? 1.0 : 0.0, clampDistance, r.motionPx);
  // Adaptive mode sends pixels off the previous frame to FXAA whether or not the resolve
  // rejected them there.
  if (kRejectMask) imageStore(rejectOut, q, uvec4(v.offscreen ? TAA_REJECT_OFFSCREEN : v.reason));
}
