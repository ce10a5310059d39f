// How much of the current sample goes into the output (alpha; 1 - alpha is the
// history's weight), after the dynamic-alpha techniques.
#ifndef TAA_BLEND_WEIGHT_GLSL
#define TAA_BLEND_WEIGHT_GLSL

// Lottes: similar lumas (a stable pixel) lean on history (alpha_min); a large
// relative difference trusts the current frame more (toward alpha_max). The 0.2
// floor keeps dark pixels from dividing by zero.
float lottesAlpha(TaaSettings s, float lumaCurrent, float lumaHistory) {
  float diff = abs(lumaCurrent - lumaHistory) / max(max(lumaCurrent, lumaHistory), 0.2);
  float similarity = 1.0 - clamp(diff, 0.0, 1.0);
  return mix(s.alpha_max, s.alpha_min, similarity * similarity);
}

// Karis (SIGGRAPH 2014, "reduce blend factor when history is near clamping"): the closer
// the history's luma came to the box edge, the likelier it is to flicker in and out of
// clamping, so the current frame's weight drops there (to half on the edge) and the
// history smooths it. t = 1 at the box centre, 0 on the edge; a flat box counts as on
// the edge. (Raising alpha instead, as the seed's wording suggests, tripled the
// frame-to-frame change of jittered HDR highlights: tests/effects/dynamic_alpha_test.cpp.)
float reduceBlendNearClamp(float alpha, float lumaHistory, float lo, float hi) {
  float halfExtent = 0.5 * (hi - lo);
  float t = halfExtent > 1e-7 ? clamp(min(lumaHistory - lo, hi - lumaHistory) / halfExtent, 0.0, 1.0) : 0.0;
  return alpha * (0.5 + 0.5 * t);
}

float velocityAlpha(TaaSettings s, float alpha, float speedPx) {
  return mix(alpha, 1.0, clamp(speedPx / s.velocity_alpha_px, 0.0, 1.0));
}

// Seed 001 (Intel's updated dynamic resolution sample): "if the pixel in the last frame was
// 1 pixel away it is attenuated by 1/2", with the distance in pixels of the resolution in use.
// The seed states that one point only; the history weight (1 - alpha) / (1 + distance) is
// the simplest curve through it that keeps a still pixel's weight (docs/techniques.md).
float velocityAttenuation(float alpha, float distancePx) {
  return 1.0 - (1.0 - alpha) / (1.0 + max(distancePx, 0.0));
}

#endif
