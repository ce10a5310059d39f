// Where this pixel was last frame: from the motion-vector buffer, or from depth
// and the inverse view-projection (static geometry under camera motion).
#ifndef TAA_REPROJECTION_GLSL
#define TAA_REPROJECTION_GLSL

// Linear view distance from a reversed-Z depth value (1 at near, 0 at far).
float linearDepth(float d) {
  float n = taaUniforms.planes.x, f = taaUniforms.planes.y;
  return n * f / (n + d * (f - n));
}

// The render pixel whose velocity this pixel uses: itself, the longest motion in
// 3x3, or the nearest surface in 3x3 (largest reversed-Z depth), which keeps
// silhouettes of moving objects from trailing.
ivec2 velocityPixel(ivec2 p, ivec2 hi) {
  if (kVelocitySampling == 0) return p;
  ivec2 best = p;
  float bestKey = -1.0;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 q = clamp(p + ivec2(i, j), ivec2(0), hi);
      float key = kVelocitySampling == 1 ? dot(texelFetch(velocityTex, q, 0).xy, texelFetch(velocityTex, q, 0).xy)
                                         : texelFetch(depthTex, q, 0).r;
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

Reprojection reprojectDepth(vec2 uv, float depth) {
  vec4 world = taaUniforms.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec4 prevClip = taaUniforms.prevViewProj * vec4(world.xyz / world.w, 1.0);
  Reprojection r;
  r.prevUv = prevClip.w > 0.0 ? prevClip.xy / prevClip.w * 0.5 + 0.5 : vec2(-1.0);
  r.expectedDepth = prevClip.w;
  r.motionPx = (uv - r.prevUv) * taaUniforms.outputSize.xy;
  return r;
}

// Velocity is in pixels of this frame's render size, so dividing by that size
// (not the output or allocation size) keeps it right under dynamic resolution.
Reprojection reprojectVelocity(vec2 uv, vec2 velocityPx, float depth) {
  Reprojection r;
  r.prevUv = uv - velocityPx * taaUniforms.renderSize.zw;
  r.expectedDepth = linearDepth(depth);
  r.motionPx = velocityPx * taaUniforms.outputSize.xy * taaUniforms.renderSize.zw;
  return r;
}

Reprojection reproject(vec2 uv, ivec2 p, ivec2 hi) {
  ivec2 vp = velocityPixel(p, hi);
  float depth = texelFetch(depthTex, vp, 0).r;
  bool useVelocity = kUseVelocity == 2 || (kUseVelocity == 1 && (texelFetch(idsTex, vp, 0).r & IDS_MOVER_BIT) != 0u);
  if (useVelocity) return reprojectVelocity(uv, texelFetch(velocityTex, vp, 0).xy, depth);
  return reprojectDepth(uv, depth);
}

#endif
