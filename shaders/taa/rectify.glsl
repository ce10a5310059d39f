// History rectification against the neighbourhood box (working space).
#ifndef TAA_RECTIFY_GLSL
#define TAA_RECTIFY_GLSL

vec3 clampToBox(vec3 h, Box b) { return clamp(h, b.lo, b.hi); }

// Moves h along the segment toward the box centre until it lies inside the box;
// points already inside stay. The box is widened by one half-float step of its
// largest bound, in every channel: history is stored in half floats (rounded toward
// zero on lavapipe), so a converged history sits up to a step outside a box it belongs
// to (in YCoCg the step of Y shows up in Co and Cg too), and clipping it would pull
// every channel toward the centre, frame after frame, without end.
vec3 clipToBox(vec3 h, Box b) {
  vec3 center = 0.5 * (b.lo + b.hi);
  vec3 bound = max(abs(b.lo), abs(b.hi));
  vec3 extent = 0.5 * (b.hi - b.lo) + max(bound.x, max(bound.y, bound.z)) * (1.0 / 1024.0);
  vec3 offset = h - center;
  vec3 units = abs(offset) / max(extent, vec3(1e-7));
  float m = max(units.x, max(units.y, units.z));
  return m > 1.0 ? center + offset / m : h;
}

#if TAA_VALUE_COUNT(TAA_RECTIFY_VALUES) != 3
#error "rectifyHistory: a taa.rectify value without its branch"
#endif
vec3 rectifyHistory(TaaSettings s, vec3 h, Box b) {
  if (s.rectify == RECTIFY_CLAMP) return clampToBox(h, b);
  if (s.rectify == RECTIFY_CLIP) return clipToBox(h, b);
  return h;  // RECTIFY_NONE
}

#endif
