// Sample-count accumulation: each pixel averages the samples it has seen since its history
// was last invalid (1/n weights up to `max_samples`, then an exponential window), with the
// history clamped to the current 3x3 box widened by the pixel's own temporal spread.
// Two history targets of its own carry what the output alone cannot: the count and the
// second moment. Written only against the installed taa_user.h (docs/user-taa.md).
#version 450
#define TAA_USE_VELOCITY
#define TAA_HISTORY0_FORMAT rgba16f  // rgb: accumulated mean colour, a: samples in it
#define TAA_HISTORY1_FORMAT r32f     // mean of the squared luma over the same samples
#include "taa_user.h"

layout(constant_id = 0) const float max_samples = 10.0;
layout(constant_id = 1) const float spread = 1.0;  // temporal standard deviations the box widens by

float luma(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

vec3 finiteColor(ivec2 p) {
  vec3 c = taa_color_at(p);
  return any(isnan(c)) || any(isinf(c)) ? vec3(0.0) : c;
}

void restart(ivec2 p, vec3 current) {
  imageStore(taa_output, p, vec4(current, 1.0));
  imageStore(taa_history0_out, p, vec4(current, 1.0));
  imageStore(taa_history1_out, p, vec4(luma(current) * luma(current)));
}

void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 rp = taa_render_pixel(p);
  vec3 current = finiteColor(rp);
  if (!taa_has_history()) {
    restart(p, current);
    return;
  }
  vec2 velocity = texelFetch(taa_velocity, rp, 0).xy * taa_frame.outputSize.xy * taa_frame.renderSize.zw;
  vec2 uv = (vec2(p) + 0.5 - velocity) * taa_frame.outputSize.zw;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) {
    restart(p, current);
    return;
  }
  vec4 h = texture(taa_history0, uv);
  float m2 = texture(taa_history1, uv).r;
  float sigma = sqrt(max(m2 - luma(h.rgb) * luma(h.rgb), 0.0));

  vec3 lo = current, hi = current;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      vec3 c = finiteColor(rp + ivec2(dx, dy));
      lo = min(lo, c);
      hi = max(hi, c);
    }
  vec3 mean = clamp(h.rgb, lo - spread * sigma, hi + spread * sigma);
  // A history the box had to move far is another surface's: start counting again.
  float n = distance(mean, h.rgb) > 0.5 * (luma(hi) - luma(lo)) + 1e-3 ? 1.0 : min(h.a + 1.0, max_samples);
  vec3 result = mix(mean, current, 1.0 / n);
  imageStore(taa_output, p, vec4(result, 1.0));
  imageStore(taa_history0_out, p, vec4(result, n));
  imageStore(taa_history1_out, p, vec4(mix(n > 1.0 ? m2 : 0.0, luma(current) * luma(current), 1.0 / n)));
}
