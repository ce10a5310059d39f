// Helpers shared by the post passes: every pass reads HDR colour that may hold NaN
// or Inf (a broken input must stay confined to its own pixel), and the filters that
// expect [0,1] signals (CAS, FXAA) work through an invertible tonemap.
#ifndef POST_COMMON_GLSL
#define POST_COMMON_GLSL

const float kHalfMax = 65504.0;

bool isFinite3(vec3 c) { return !any(isnan(c)) && !any(isinf(c)); }

// NaN -> 0, then [0, half max]: min/max/clamp do not scrub NaN on their own (the
// result of comparing with NaN is implementation-defined), so the select comes first.
vec3 scrub(vec3 c) { return clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(kHalfMax)); }

// c / (1 + c) maps [0, half max] into [0, 1) per channel, monotonically, so min/max
// and orderings survive the round trip.
vec3 tonemap(vec3 c) { return c / (1.0 + c); }

// The inverse of tonemap; t stays below 1 for finite input, the floor only guards
// against rounding at the top of the range.
vec3 untonemap(vec3 t) { return min(t / max(1.0 - t, vec3(1.0 / kHalfMax)), vec3(kHalfMax)); }

#endif
