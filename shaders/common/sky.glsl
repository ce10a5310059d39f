// The sky's colour by view direction: drawn by sky.frag where no geometry is, and
// returned by the adaptive tracer for rays that miss, so the two agree.
#ifndef TAA_SKY_GLSL
#define TAA_SKY_GLSL

vec3 skyColor(vec3 dir) {
  float up = clamp(dir.y, -1.0, 1.0);
  vec3 horizon = vec3(0.55, 0.62, 0.70);
  vec3 zenith = vec3(0.18, 0.32, 0.62);
  vec3 ground = vec3(0.22, 0.20, 0.18);
  return up >= 0.0 ? mix(horizon, zenith, sqrt(up)) : mix(horizon, ground, sqrt(-up));
}

#endif
