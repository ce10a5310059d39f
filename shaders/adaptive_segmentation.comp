#version 450
// Adaptive ray tracing's segmentation (Marrs et al.), after the resolve: a pixel is
// traced when the weighted sum of its screen-space derivative terms exceeds the
// threshold, or when it was so marked within the last history_count frames; a pixel
// that is not traced but had no usable history is marked for FXAA. Each term is the
// largest change to a 4-neighbour, scaled into [0, 1]:
//   normal    (1 - cos) / 2 of the angle between the normals,
//   depth     relative linear-depth difference, at most 1,
//   material  1 where the ids differ (object, material, or sky against geometry),
//   luminance difference of tonemapped luma c / (1 + c).
// The history counter is per pixel, in screen space (not reprojected): a pixel marked
// now counts down from history_count, and stays traced while its count lasts.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = SEG_SPEC_HAS_HISTORY) const bool kHasHistory = true;
layout(constant_id = SEG_SPEC_TRACE_ALL) const bool kTraceAll = false;
layout(constant_id = SEG_SPEC_FXAA) const bool kFxaa = true;
layout(constant_id = SEG_SPEC_TRACE_DISOCCLUDED) const bool kTraceDisoccluded = false;
layout(constant_id = SEG_SPEC_DEBUG) const bool kDebug = false;
layout(constant_id = SEG_SPEC_FXAA_BORDER) const int kFxaaBorder = 0;

layout(std140, binding = SEG_BINDING_UNIFORMS) uniform SegBlock { SegmentationUniforms seg; };
layout(binding = SEG_BINDING_COLOR) uniform sampler2D colorTex;
layout(binding = SEG_BINDING_DEPTH) uniform sampler2D depthTex;
layout(binding = SEG_BINDING_NORMAL) uniform sampler2D normalTex;
layout(binding = SEG_BINDING_IDS) uniform usampler2D idsTex;
layout(binding = SEG_BINDING_REJECTION) uniform usampler2D rejectionTex;
layout(binding = SEG_BINDING_COUNTER, r32ui) uniform uimage2D counterImage;
layout(binding = SEG_BINDING_MASK, r32ui) uniform writeonly uimage2D maskImage;
layout(std430, binding = SEG_BINDING_COUNTS) buffer CountsBlock { AdaptiveCounts counts; };
layout(binding = SEG_BINDING_RESOLVED) uniform sampler2D resolvedTex;
layout(binding = SEG_BINDING_DEBUG, rgba16f) uniform writeonly image2D debugImage;

struct Texel {
  vec3 normal;
  float depth;  // linear
  uint ids;
  float luma;
};

Texel texelAt(ivec2 p) {
  Texel t;
  t.normal = texelFetch(normalTex, p, 0).xyz;
  float d = texelFetch(depthTex, p, 0).r;
  float n = seg.params.z, f = seg.params.w;
  t.depth = n * f / (n + d * (f - n));  // reversed Z: 1 near, 0 far
  t.ids = texelFetch(idsTex, p, 0).r;
  vec3 c = max(texelFetch(colorTex, p, 0).rgb, vec3(0.0));
  c = mix(c, vec3(0.0), isnan(c));
  t.luma = dot(c / (1.0 + c), vec3(0.2126, 0.7152, 0.0722));
  return t;
}

// The four terms, each the largest over the 4-neighbourhood.
vec4 derivativeTerms(ivec2 p) {
  ivec2 hi = ivec2(seg.size.xy) - 1;
  Texel c = texelAt(p);
  vec4 terms = vec4(0.0);
  const ivec2 kOffsets[4] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int i = 0; i < 4; ++i) {
    ivec2 q = p + kOffsets[i];
    if (any(lessThan(q, ivec2(0))) || any(greaterThan(q, hi))) continue;
    Texel o = texelAt(q);
    // Sky has a zero normal: its boundary is the material term's, not the normal's.
    bool bothSurfaces = c.ids != IDS_SKY && o.ids != IDS_SKY;
    float normalTerm = bothSurfaces ? 0.5 * (1.0 - clamp(dot(c.normal, o.normal), -1.0, 1.0)) : 0.0;
    float depthTerm = min(abs(c.depth - o.depth) / max(min(c.depth, o.depth), 1e-20), 1.0);
    float materialTerm = c.ids != o.ids ? 1.0 : 0.0;
    float lumaTerm = abs(c.luma - o.luma);
    terms = max(terms, vec4(normalTerm, depthTerm, materialTerm, lumaTerm));
  }
  return terms;
}

vec3 debugColor(uint mark, ivec2 p) {
  if (mark == ADAPTIVE_MASK_TRACE) return vec3(1.0, 0.85, 0.0);
  if (mark == ADAPTIVE_MASK_TRACE_HISTORY) return vec3(1.0, 0.45, 0.0);
  if (mark == ADAPTIVE_MASK_FXAA) return vec3(0.1, 0.35, 1.0);
  // The rest is the output in dim grey, so the marks can be placed in the image.
  vec3 c = max(texelFetch(resolvedTex, p, 0).rgb, vec3(0.0));
  return vec3(0.3 * dot(c / (1.0 + c), vec3(0.2126, 0.7152, 0.0722)));
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(p, ivec2(seg.size.xy)))) return;

  float score = dot(seg.weights, derivativeTerms(p));
  bool marked = kTraceAll || score > seg.params.x;
  uint historyCount = uint(seg.params.y);
  uint left = kHasHistory ? imageLoad(counterImage, p).r : 0u;
  uint rejection = texelFetch(rejectionTex, p, 0).r;
  // Disoccluded: a test rejected the history on screen (whichever test it was).
  if (kTraceDisoccluded && rejection >= TAA_REJECT_FIRST_ON_SCREEN) marked = true;

  uint mark = ADAPTIVE_MASK_NONE;
  if (marked) mark = ADAPTIVE_MASK_TRACE;
  else if (left > 0u) mark = ADAPTIVE_MASK_TRACE_HISTORY;
  else if (kFxaa && rejection != TAA_REJECT_NONE) mark = ADAPTIVE_MASK_FXAA;
  // adaptive.fxaa_debug_border: the seed's debug frame, FXAA whatever else marked the pixel.
  if (kFxaaBorder > 0 &&
      (any(lessThan(p, ivec2(kFxaaBorder))) || any(greaterThanEqual(p, ivec2(seg.size.xy) - kFxaaBorder))))
    mark = ADAPTIVE_MASK_FXAA;
  imageStore(counterImage, p, uvec4(marked ? historyCount : (left > 0u ? left - 1u : 0u)));
  imageStore(maskImage, p, uvec4(mark));

  // Integer sums: the totals do not depend on the order the invocations run in.
  bool traced = mark == ADAPTIVE_MASK_TRACE || mark == ADAPTIVE_MASK_TRACE_HISTORY;
  if (traced) atomicAdd(counts.traced, 1u);
  if (mark == ADAPTIVE_MASK_FXAA) atomicAdd(counts.fxaa, 1u);
  if (kDebug) imageStore(debugImage, p, vec4(debugColor(mark, p), 1.0));
}
