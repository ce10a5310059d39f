// History rectification against the neighbourhood box (working space).
#ifndef TAA_RECTIFY_GLSL
#define TAA_RECTIFY_GLSL

vec3 clampToBox(vec3 h, Box b) { return clamp(h, b.lo, b.hi); }

// Moves h along the segment toward the box centre until it lies inside the box;
// points already inside stay. A flat box (zero extent) collapses h onto the centre.
vec3 clipToBox(vec3 h, Box b) {
  vec3 center = 0.5 * (b.lo + b.hi);
  vec3 extent = 0.5 * (b.hi - b.lo);
  vec3 offset = h - center;
  vec3 units = abs(offset) / max(extent, vec3(1e-7));
  float m = max(units.x, max(units.y, units.z));
  return m > 1.0 ? center + offset / m : h;
}

vec3 rectifyHistory(vec3 h, Box b) {
  if (kRectify == 1) return clampToBox(h, b);
  if (kRectify == 2) return clipToBox(h, b);
  return h;
}

#endif
