// Geometric consistency (as in SVGF's temporal accumulation): each history tap is
// used only if last frame's surface there matches this pixel's in mesh id, depth and
// normal. The 2x2 bilinear footprint comes first, then the 3x3 around it; if no tap
// is consistent, the history is rejected.
#ifndef TAA_CONSISTENCY_GLSL
#define TAA_CONSISTENCY_GLSL

// Where the consistent history came from.
#define CONSISTENCY_FOOTPRINT_2X2 0
#define CONSISTENCY_FOOTPRINT_3X3 1
#define CONSISTENCY_REJECTED 2

struct Consistent {
  vec3 color;
  int level;  // one of CONSISTENCY_*
};

// The previous frame's G-buffer a tap is tested against.
#define TAA_PREV_GBUFFER_PARAMS usampler2D prevIdsTex, sampler2D prevDepthTex, sampler2D prevNormalTex

bool tapConsistent(TaaSettings s, TaaUniforms u, TAA_PREV_GBUFFER_PARAMS, ivec2 historyPixel, uint ids,
                   float expectedDepth, vec3 normal) {
  // History pixels map to last frame's render pixels by their centres.
  vec2 uv = (vec2(historyPixel) + 0.5) * u.outputSize.zw;
  ivec2 q = prevRenderPixel(u, uv);
  if ((texelFetch(prevIdsTex, q, 0).r & 0x7fffffffu) != (ids & 0x7fffffffu)) return false;
  // Sky against sky is the same "surface": it has no depth to compare and no normal.
  if ((ids & 0x7fffffffu) == IDS_SKY) return true;
  float prevDepth = linearDepth(u, texelFetch(prevDepthTex, q, 0).r);
  if (abs(prevDepth - expectedDepth) > s.consistency_depth * max(expectedDepth, 1e-20)) return false;
  return dot(texelFetch(prevNormalTex, q, 0).xyz, normal) >= s.consistency_normal;
}

Consistent consistentHistory(TaaSettings s, TaaUniforms u, sampler2D historyTex, TAA_PREV_GBUFFER_PARAMS,
                             vec2 prevUv, uint ids, float expectedDepth, vec3 normal) {
  ivec2 hi = ivec2(u.outputSize.xy) - 1;
  vec2 p = prevUv * u.outputSize.xy - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 f = p - floor(p);
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 t = base + ivec2(i, j);
      if (any(lessThan(t, ivec2(0))) || any(greaterThan(t, hi))) continue;
      if (!tapConsistent(s, u, prevIdsTex, prevDepthTex, prevNormalTex, t, ids, expectedDepth, normal)) continue;
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      sum += texelFetch(historyTex, t, 0).rgb * w;
      weight += w;
    }
  if (weight > 1e-6) return Consistent(sum / weight, CONSISTENCY_FOOTPRINT_2X2);
  // Thin geometry (foliage, wires) often misses the 2x2 footprint: widen to 3x3.
  ivec2 center = ivec2(floor(prevUv * u.outputSize.xy));
  sum = vec3(0.0);
  float n = 0.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 t = center + ivec2(i, j);
      if (any(lessThan(t, ivec2(0))) || any(greaterThan(t, hi))) continue;
      if (!tapConsistent(s, u, prevIdsTex, prevDepthTex, prevNormalTex, t, ids, expectedDepth, normal)) continue;
      sum += texelFetch(historyTex, t, 0).rgb;
      n += 1.0;
    }
  if (n > 0.0) return Consistent(sum / n, CONSISTENCY_FOOTPRINT_3X3);
  return Consistent(vec3(0.0), CONSISTENCY_REJECTED);
}

#endif
