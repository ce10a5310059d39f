// Velocity reprojection and variance clipping (Salvi 2016): history is fetched where the
// pixel was last frame, then clipped towards the neighbourhood mean into the box
// mean +- gamma * sigma, intersected with the min/max box so it never leaves the range of
// the current colours. Written only against the installed taa_user.h (docs/user-taa.md).
#version 450
#define TAA_USE_VELOCITY
#include "taa_user.h"

layout(constant_id = 0) const float alpha = 0.1;   // weight of the current frame
layout(constant_id = 1) const float gamma = 1.0;   // box half-size in standard deviations

// Moves `history` along the line to `center` until it lies inside [lo, hi].
vec3 clipToBox(vec3 history, vec3 center, vec3 lo, vec3 hi) {
  vec3 d = history - center;
  vec3 extent = max(hi - center, center - lo);
  vec3 t = abs(d) / max(extent, vec3(1e-6));
  float m = max(t.x, max(t.y, t.z));
  return m > 1.0 ? center + d / m : history;
}

// A NaN or infinite input sample would poison the history for good; count it as black.
vec3 finiteColor(ivec2 p) {
  vec3 c = taa_color_at(p);
  return any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : c;
}

void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 rp = taa_render_pixel(p);
  vec3 current = finiteColor(rp);
  if (!taa_has_history()) {
    imageStore(taa_output, p, vec4(current, 1.0));
    return;
  }
  vec3 lo = current, hi = current, m1 = vec3(0.0), m2 = vec3(0.0);
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      vec3 c = finiteColor(rp + ivec2(dx, dy));
      lo = min(lo, c);
      hi = max(hi, c);
      m1 += c;
      m2 += c * c;
    }
  vec3 mean = m1 / 9.0;
  vec3 sigma = sqrt(max(m2 / 9.0 - mean * mean, vec3(0.0)));
  vec3 boxLo = max(mean - gamma * sigma, lo), boxHi = min(mean + gamma * sigma, hi);

  // Velocity is in render pixels; the history lives at output size.
  vec2 velocity = texelFetch(taa_velocity, rp, 0).xy * taa_frame.outputSize.xy * taa_frame.renderSize.zw;
  vec2 uv = (vec2(p) + 0.5 - velocity) * taa_frame.outputSize.zw;
  bool offscreen = any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)));
  vec3 history = texture(taa_prev_output, uv).rgb;
  history = clipToBox(history, clamp(mean, lo, hi), boxLo, boxHi);
  // Clipping can leave rounding outside the min/max box; the declared bound is that box.
  history = clamp(history, lo, hi);
  vec3 result = offscreen ? current : mix(history, current, alpha);
  imageStore(taa_output, p, vec4(result, 1.0));
}
