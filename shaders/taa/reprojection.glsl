// Where this pixel was last frame: from the motion-vector buffer, or from depth
// and the inverse view-projection (static geometry under camera motion).
#ifndef TAA_REPROJECTION_GLSL
#define TAA_REPROJECTION_GLSL

// Linear view distance from a reversed-Z depth value (1 at near, 0 at far).
float linearDepth(TaaUniforms u, float d) {
  float n = u.view.x, f = u.view.y;
  return n * f / (n + d * (f - n));
}

#if TAA_VALUE_COUNT(TAA_VELOCITY_SAMPLING_VALUES) != 3
#error "velocityKey, velocityPixel: a taa.velocity_sampling value without its branch"
#endif
#if TAA_VALUE_COUNT(TAA_USE_VELOCITY_VALUES) != 3
#error "reproject: a taa.use_velocity value without its branch"
#endif

// What velocity sampling maximises: squared motion (longest) or reversed-Z depth (closest).
float velocityKey(TaaSettings s, sampler2D velocityTex, sampler2D depthTex, ivec2 q) {
  if (s.velocity_sampling == VELOCITY_SAMPLING_LONGEST_3X3) {
    vec2 v = texelFetch(velocityTex, q, 0).xy;
    return dot(v, v);
  }
  return texelFetch(depthTex, q, 0).r;  // VELOCITY_SAMPLING_CLOSEST_3X3
}

// The render pixel whose velocity this pixel uses: itself, the longest motion in
// 3x3, or the nearest surface in 3x3 (largest reversed-Z depth), which keeps
// silhouettes of moving objects from trailing.
ivec2 velocityPixel(TaaSettings s, sampler2D velocityTex, sampler2D depthTex, ivec2 p, ivec2 hi) {
  if (s.velocity_sampling == VELOCITY_SAMPLING_PIXEL) return p;
  // The pixel itself is the first candidate and a neighbour must beat it strictly, so ties
  // (a still view, where every velocity is zero; a flat depth) keep the pixel's own depth and
  // ids instead of the (-1,-1) neighbour's.
  ivec2 best = p;
  float bestKey = velocityKey(s, velocityTex, depthTex, p);
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 q = clamp(p + ivec2(i, j), ivec2(0), hi);
      float key = velocityKey(s, velocityTex, depthTex, q);
      if (key > bestKey) {
        bestKey = key;
        best = q;
      }
    }
  return best;
}

struct Reprojection {
  vec2 prevUv;         // history position (0..1)
  float expectedDepth; // linear distance the surface should have had last frame
  vec2 motionPx;       // screen motion in output pixels, for velocity-driven alpha
};

Reprojection reprojectDepth(TaaUniforms u, vec2 uv, float depth) {
  vec4 world = u.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec4 prevClip = u.prevViewProj * vec4(world.xyz / world.w, 1.0);
  Reprojection r;
  r.prevUv = prevClip.w > 0.0 ? prevClip.xy / prevClip.w * 0.5 + 0.5 : vec2(-1.0);
  r.expectedDepth = prevClip.w;
  r.motionPx = (uv - r.prevUv) * u.outputSize.xy;
  return r;
}

// Velocity is in pixels of this frame's render size, so dividing by that size
// (not the output or allocation size) keeps it right under dynamic resolution.
// The expected depth is the one the surface had last frame, as on the depth path: the
// world position under the previous camera. (The velocity buffer is 2D, so a mover's own
// motion in depth is not in it; this frame's depth, used before, also missed the camera's.)
Reprojection reprojectVelocity(TaaUniforms u, vec2 uv, vec2 velocityPx, float depth) {
  Reprojection r;
  r.prevUv = uv - velocityPx * u.renderSize.zw;
  r.expectedDepth = reprojectDepth(u, uv, depth).expectedDepth;
  r.motionPx = velocityPx * u.outputSize.xy * u.renderSize.zw;
  return r;
}

Reprojection reproject(TaaSettings s, TaaUniforms u, sampler2D depthTex, sampler2D velocityTex, usampler2D idsTex,
                       vec2 uv, ivec2 p, ivec2 hi) {
  ivec2 vp = velocityPixel(s, velocityTex, depthTex, p, hi);
  float depth = texelFetch(depthTex, vp, 0).r;
  bool useVelocity = s.use_velocity == USE_VELOCITY_ALL ||
                     (s.use_velocity == USE_VELOCITY_MOVERS && (texelFetch(idsTex, vp, 0).r & IDS_MOVER_BIT) != 0u);
  if (useVelocity) return reprojectVelocity(u, uv, texelFetch(velocityTex, vp, 0).xy, depth);
  return reprojectDepth(u, uv, depth);  // USE_VELOCITY_OFF, or a static pixel under MOVERS
}

#endif
