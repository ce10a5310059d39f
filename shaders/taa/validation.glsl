// History rejection tests that need no colour: off-screen, depth culling and the
// dynamic anti-ghosting heuristic.
#ifndef TAA_VALIDATION_GLSL
#define TAA_VALIDATION_GLSL

bool offscreen(vec2 uv) { return any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))); }

ivec2 prevRenderPixel(TaaUniforms u, vec2 uv) {
  ivec2 hi = ivec2(u.prevRenderSize.xy) - 1;
  return clamp(ivec2(floor(uv * u.prevRenderSize.xy)), ivec2(0), hi);
}

// The surface seen last frame at the reprojected position is not the one we expect.
bool depthRejects(TaaSettings s, TaaUniforms u, sampler2D prevDepthTex, Reprojection r) {
  float prev = linearDepth(u, texelFetch(prevDepthTex, prevRenderPixel(u, r.prevUv), 0).r);
  float expected = max(r.expectedDepth, 1e-20);
  return abs(prev - expected) > s.depth_threshold * expected;
}

bool moverMoving(uint ids, vec2 velocity) { return (ids & IDS_MOVER_BIT) != 0u && dot(velocity, velocity) > 1e-4; }

// A mover crossed this pixel last frame and nothing moves around it now: what the
// history holds is the mover's trail, not the background.
bool antiGhostRejects(TaaUniforms u, usampler2D idsTex, sampler2D velocityTex, usampler2D prevIdsTex,
                      sampler2D prevVelocityTex, ivec2 p, ivec2 hi, vec2 uv) {
  const ivec2 cross5[5] = ivec2[](ivec2(0, 0), ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int i = 0; i < 5; ++i) {
    ivec2 q = clamp(p + cross5[i], ivec2(0), hi);
    if (moverMoving(texelFetch(idsTex, q, 0).r, texelFetch(velocityTex, q, 0).xy)) return false;
  }
  ivec2 prev = prevRenderPixel(u, uv);
  return moverMoving(texelFetch(prevIdsTex, prev, 0).r, texelFetch(prevVelocityTex, prev, 0).xy);
}

#endif
