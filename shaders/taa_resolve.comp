#version 450
// The temporal resolve: one output pixel per invocation. Every technique is a
// specialization constant, so a case's pipeline contains only what it enables.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = TAA_SPEC_MODE) const int kMode = 2;
layout(constant_id = TAA_SPEC_HAS_HISTORY) const bool kHasHistory = true;
layout(constant_id = TAA_SPEC_TONE_WEIGHT) const int kToneWeight = 0;
layout(constant_id = TAA_SPEC_USE_VELOCITY) const int kUseVelocity = 2;
layout(constant_id = TAA_SPEC_VELOCITY_SAMPLING) const int kVelocitySampling = 0;
layout(constant_id = TAA_SPEC_HISTORY_FILTER) const int kHistoryFilter = 0;
layout(constant_id = TAA_SPEC_REJECT_OFFSCREEN) const bool kRejectOffscreen = true;
layout(constant_id = TAA_SPEC_DEPTH_CULLING) const bool kDepthCulling = false;
layout(constant_id = TAA_SPEC_CONSISTENCY) const bool kConsistency = false;
layout(constant_id = TAA_SPEC_ANTI_GHOSTING) const bool kAntiGhosting = false;
layout(constant_id = TAA_SPEC_RECTIFY) const int kRectify = 0;
layout(constant_id = TAA_SPEC_VARIANCE_CLIP) const bool kVarianceClip = false;
layout(constant_id = TAA_SPEC_SHAPED) const bool kShaped = false;
layout(constant_id = TAA_SPEC_YCOCG) const bool kYCoCg = false;
layout(constant_id = TAA_SPEC_SHRINK_CHROMA) const bool kShrinkChroma = false;
layout(constant_id = TAA_SPEC_LUMA_WEIGHT) const bool kLumaWeight = false;
layout(constant_id = TAA_SPEC_VELOCITY_ALPHA) const bool kVelocityAlpha = false;
layout(constant_id = TAA_SPEC_REDUCE_BLEND) const bool kReduceBlend = false;
layout(constant_id = TAA_SPEC_VELOCITY_IN_ALPHA) const bool kVelocityInAlpha = false;
layout(constant_id = TAA_SPEC_UPSAMPLE) const bool kUpsample = false;
layout(constant_id = TAA_SPEC_DEBUG) const int kDebug = 0;
layout(constant_id = TAA_SPEC_REJECT_MASK) const bool kRejectMask = false;
layout(constant_id = TAA_SPEC_HALF_HISTORY) const bool kHalfHistory = true;

layout(std140, binding = TAA_BINDING_UNIFORMS) uniform TaaBlock { TaaUniforms taaUniforms; };
layout(binding = TAA_BINDING_COLOR) uniform sampler2D colorTex;
layout(binding = TAA_BINDING_DEPTH) uniform sampler2D depthTex;
layout(binding = TAA_BINDING_VELOCITY) uniform sampler2D velocityTex;
layout(binding = TAA_BINDING_IDS) uniform usampler2D idsTex;
layout(binding = TAA_BINDING_NORMAL) uniform sampler2D normalTex;
layout(binding = TAA_BINDING_HISTORY) uniform sampler2D historyTex;
layout(binding = TAA_BINDING_PREV_DEPTH) uniform sampler2D prevDepthTex;
layout(binding = TAA_BINDING_PREV_NORMAL) uniform sampler2D prevNormalTex;
layout(binding = TAA_BINDING_PREV_IDS) uniform usampler2D prevIdsTex;
layout(binding = TAA_BINDING_PREV_VELOCITY) uniform sampler2D prevVelocityTex;
layout(binding = TAA_BINDING_HISTORY_OUT) uniform writeonly image2D historyOut;
layout(binding = TAA_BINDING_DEBUG_OUT, rgba16f) uniform writeonly image2D debugOut;
layout(binding = TAA_BINDING_REJECT_OUT, r32ui) uniform writeonly uimage2D rejectOut;

#include "taa/color_space.glsl"
#include "taa/history_filter.glsl"
#include "taa/neighborhood.glsl"
#include "taa/rectify.glsl"
#include "taa/reprojection.glsl"
#include "taa/validation.glsl"
#include "taa/consistency.glsl"
#include "taa/blend_weight.glsl"

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

void writeOutput(ivec2 q, vec3 color, float rejected, float clampDistance, vec2 motionPx) {
  vec3 bounded = boundColor(color);
  imageStore(historyOut, q, vec4(kHalfHistory ? roundToHalf(bounded) : bounded, 1.0));
  if (kDebug == 1) imageStore(debugOut, q, vec4(motionPx * taaUniforms.limits.w * 0.5 + 0.5, 0.0, 1.0));
  if (kDebug == 2) imageStore(debugOut, q, vec4(rejected, 0.0, 0.0, 1.0));
  if (kDebug == 3) imageStore(debugOut, q, vec4(vec3(clampDistance * taaUniforms.limits.w), 1.0));
}

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(q, ivec2(taaUniforms.outputSize.xy)))) return;
  ivec2 hi = ivec2(taaUniforms.renderSize.xy) - 1;
  vec2 uv = (vec2(q) + 0.5) * taaUniforms.outputSize.zw;

  if (kMode == 0) {  // pass-through: the input, bit for bit
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
      vec3 c = texelFetch(colorTex, clamp(cur.pixel + ivec2(i, j), ivec2(0), hi), 0).rgb;
      valid[k] = !any(isnan(c));
      c = clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(kHalfMax));  // +Inf -> half max
      taps[k] = toWorking(c);
      if (k == 4) centre = c;
      if (valid[k]) {
        finiteSum += c;
        finiteCount += 1.0;
      }
    }
  vec3 current = valid[4] ? centre : (finiteCount > 0.0 ? finiteSum / finiteCount : vec3(0.0));

  if (!kHasHistory) {
    writeOutput(q, current, 1.0, 0.0, vec2(0.0));
    if (kRejectMask) imageStore(rejectOut, q, uvec4(TAA_REJECT_NO_HISTORY));
    return;
  }

  if (kMode == 1) {  // basic: the same pixel last frame, no reprojection, no rejection
    vec3 h = texelFetch(historyTex, q, 0).rgb;
    writeOutput(q, toneWeightedBlend(h, current, taaUniforms.blend.x * cur.weight), 0.0, 0.0, vec2(0.0));
    return;
  }

  Reprojection r = reproject(uv, cur.pixel, hi);
  // Adaptive mode sends pixels off the previous frame to FXAA whether or not the
  // resolve rejects them, so that test is made here, before the clamp.
  bool wasOffscreen = offscreen(r.prevUv);
  bool rejected = false;
  if (kRejectOffscreen && offscreen(r.prevUv)) rejected = true;
  r.prevUv = clamp(r.prevUv, vec2(0.0), vec2(1.0));
  if (kDepthCulling && !rejected && depthRejects(r)) rejected = true;
  if (kAntiGhosting && !rejected && antiGhostRejects(cur.pixel, hi, r.prevUv)) rejected = true;

  vec3 history;
  if (kConsistency) {
    Consistent cs = consistentHistory(r.prevUv, texelFetch(idsTex, cur.pixel, 0).r,
                                      linearDepth(texelFetch(depthTex, cur.pixel, 0).r),
                                      texelFetch(normalTex, cur.pixel, 0).xyz);
    history = cs.color;
    if (cs.level == 2) rejected = true;
  } else {
    history = sampleHistory(historyTex, r.prevUv, taaUniforms.outputSize);
  }

  vec3 wHistory = toWorking(history);
  Box box = neighborhoodBox(taps, valid, toWorking(current));
  vec3 wRectified = rectifyHistory(wHistory, box);
  float clampDistance = abs(workingLuma(wRectified) - workingLuma(wHistory));

  float alpha = taaUniforms.blend.x;
  if (kLumaWeight) alpha = lottesAlpha(luma(current), luma(fromWorking(wRectified)));
  if (kReduceBlend) alpha = reduceBlendNearClamp(alpha, workingLuma(wHistory), workingLuma(box.lo), workingLuma(box.hi));
  if (kVelocityAlpha) {
    float speed = kVelocityInAlpha ? texelFetch(colorTex, cur.pixel, 0).a * taaUniforms.outputSize.x * taaUniforms.renderSize.z
                                   : length(r.motionPx);
    alpha = velocityAlpha(alpha, speed);
  }
  alpha *= cur.weight;
  if (rejected) alpha = taaUniforms.blend.y;

  vec3 result = toneWeightedBlend(fromWorking(wRectified), current, alpha);
  writeOutput(q, result, rejected ? 1.0 : 0.0, clampDistance, r.motionPx);
  if (kRejectMask)
    imageStore(rejectOut, q, uvec4(wasOffscreen ? TAA_REJECT_OFFSCREEN : rejected ? TAA_REJECT_DISOCCLUDED : TAA_REJECT_NONE));
}
