// The built-in resolve's one chain of history rejection: every test in order, the first
// that rejects naming the reason (TAA_REJECT_*, common/shared.h). The blend, the rejection
// debug view and the adaptive mask all read this verdict, so a new test is a setting, its
// function (validation.glsl or its own include, included here) and one line below.
#ifndef TAA_REJECTION_GLSL
#define TAA_REJECTION_GLSL

#include "taa/consistency.glsl"
#include "taa/history_filter.glsl"
#include "taa/validation.glsl"

struct HistoryVerdict {
  vec3 color;      // the history to blend (consistency's own taps, or the filtered history)
  uint reason;     // TAA_REJECT_NONE, or the first test that rejected it
  bool offscreen;  // the reprojected position left the previous frame, rejected there or not
};

// `p`: the render pixel of the current sample; `uv`: the output pixel's centre.
HistoryVerdict historyVerdict(TaaSettings s, TaaUniforms u TAA_INPUT_PARAMS, Reprojection r, vec2 uv,
                              ivec2 p, ivec2 hi) {
  HistoryVerdict v;
  v.offscreen = offscreen(r.prevUv);
  v.reason = TAA_REJECT_NONE;
  if (s.reject_offscreen && v.offscreen) v.reason = TAA_REJECT_OFFSCREEN;
  r.prevUv = clamp(r.prevUv, vec2(0.0), vec2(1.0));
  if (v.reason == TAA_REJECT_NONE && s.depth_culling && depthRejects(s, u, prevDepthTex, r))
    v.reason = TAA_REJECT_DEPTH;
  if (v.reason == TAA_REJECT_NONE && s.anti_ghosting &&
      antiGhostRejects(u, idsTex, velocityTex, prevIdsTex, prevVelocityTex, p, hi, r.prevUv))
    v.reason = TAA_REJECT_GHOST;

  if (s.consistency) {
    // Taps are tested against the depth this pixel's surface had last frame (its world
    // position under last frame's camera), as depth culling is; this frame's depth would
    // fail every surface whose distance changed under a dolly.
    float expectedDepth = reprojectDepth(u, uv, texelFetch(depthTex, p, 0).r).expectedDepth;
    Consistent cs = consistentHistory(s, u, historyTex, prevIdsTex, prevDepthTex, prevNormalTex, r.prevUv,
                                      texelFetch(idsTex, p, 0).r, expectedDepth, texelFetch(normalTex, p, 0).xyz);
    v.color = cs.color;
    if (v.reason == TAA_REJECT_NONE && cs.level == CONSISTENCY_REJECTED) v.reason = TAA_REJECT_INCONSISTENT;
  } else {
    v.color = sampleHistory(s, historyTex, r.prevUv, u.outputSize);
  }
  return v;
}

#endif
