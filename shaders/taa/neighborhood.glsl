// The box of plausible colours around the current pixel, built from its 3x3
// neighbourhood in the working space: min/max, optionally shaped (averaged with the
// 5-tap cross), variance-limited (mean +- gamma sigma) and chroma-shrunk (YCoCg).
#ifndef TAA_NEIGHBORHOOD_GLSL
#define TAA_NEIGHBORHOOD_GLSL

struct Box {
  vec3 lo;
  vec3 hi;
  vec3 mean;
};

// The gamma of variance clipping for a pixel moving by motionPx (output pixels) this frame.
// Motion-adaptive, as in Intel's TAA sample (GameTechDev/TAA, TAAResolve.hlsl): a velocity
// confidence 1 - speed / FRAME_VELOCITY_IN_PIXELS_DIFF (128), squared, lerps the gamma from
// MIN_VARIANCE_GAMMA 0.75 under motion to MAX_VARIANCE_GAMMA 2 at rest, so that still pixels
// keep the specular highlights a tight box cuts, and moving ones shed their trails.
float varianceGamma(TaaSettings s, vec2 motionPx) {
  if (!s.motion_adaptive_gamma) return s.variance_gamma;
  float confidence = clamp(1.0 - length(motionPx) / s.variance_gamma_velocity_px, 0.0, 1.0);
  return mix(s.variance_gamma_moving, s.variance_gamma_static, confidence * confidence);
}

// `taps` are the 3x3 samples in working space, row-major, centre at 4; `valid`
// marks the finite ones (invalid taps do not shape the box); motionPx is the pixel's
// screen motion in output pixels.
Box neighborhoodBox(TaaSettings s, vec3 taps[9], bool valid[9], vec3 center, vec2 motionPx) {
  vec3 lo = vec3(1e30), hi = vec3(-1e30), sum = vec3(0.0), sum2 = vec3(0.0);
  float n = 0.0;
  for (int i = 0; i < 9; ++i) {
    if (!valid[i]) continue;
    lo = min(lo, taps[i]);
    hi = max(hi, taps[i]);
    sum += taps[i];
    sum2 += taps[i] * taps[i];
    n += 1.0;
  }
  if (n == 0.0) return Box(center, center, center);
  Box b;
  b.mean = sum / n;
  b.lo = lo;
  b.hi = hi;
  if (s.shaped_neighborhood) {
    // The cross (centre and its 4 edge neighbours) is averaged with the full box.
    vec3 clo = center, chi = center;
    for (int i = 1; i < 9; i += 2) {
      if (!valid[i]) continue;
      clo = min(clo, taps[i]);
      chi = max(chi, taps[i]);
    }
    b.lo = 0.5 * (lo + clo);
    b.hi = 0.5 * (hi + chi);
  }
  if (s.variance_clip) {
    vec3 sigma = sqrt(max(sum2 / n - b.mean * b.mean, vec3(0.0)));
    float gamma = varianceGamma(s, motionPx);
    b.lo = max(b.lo, b.mean - gamma * sigma);
    b.hi = min(b.hi, b.mean + gamma * sigma);
    // Gamma 0 (or a flat box) leaves lo == hi at the mean.
    b.hi = max(b.hi, b.lo);
  }
  if (s.color_space == COLOR_SPACE_YCOCG && s.shrink_chroma) {
    float chromaExtent = 0.125 * (b.hi.x - b.lo.x);
    b.lo.yz = center.yz - chromaExtent;
    b.hi.yz = center.yz + chromaExtent;
  }
  return b;
}

#endif
