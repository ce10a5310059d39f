// The smallest useful TAA: blend the previous output at the same pixel (no reprojection)
// with the current colour, after clamping it to the current 3x3 neighbourhood's min/max box.
// Written only against the installed taa_user.h (docs/user-taa.md).
#version 450
#include "taa_user.h"

// Weight of the current frame; 1 turns the resolve off.
layout(constant_id = 0) const float alpha = 0.1;

void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 rp = taa_render_pixel(p);
  vec3 current = taa_color_at(rp);
  if (!taa_has_history()) {
    imageStore(taa_output, p, vec4(current, 1.0));
    return;
  }
  vec3 lo = current, hi = current;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      vec3 c = taa_color_at(rp + ivec2(dx, dy));
      lo = min(lo, c);
      hi = max(hi, c);
    }
  vec3 history = texelFetch(taa_prev_output, p, 0).rgb;
  history = clamp(history, lo, hi);
  imageStore(taa_output, p, vec4(mix(history, current, alpha), 1.0));
}
