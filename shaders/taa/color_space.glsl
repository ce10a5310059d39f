// Working colour space of the neighbourhood box and the luminance-weighted blends.
#ifndef TAA_COLOR_SPACE_GLSL
#define TAA_COLOR_SPACE_GLSL

const float kHalfMax = 65504.0;

float luma(vec3 rgb) { return dot(rgb, vec3(0.2126, 0.7152, 0.0722)); }

vec3 rgbToYCoCg(vec3 c) {
  return vec3(0.25 * c.r + 0.5 * c.g + 0.25 * c.b, 0.5 * c.r - 0.5 * c.b, -0.25 * c.r + 0.5 * c.g - 0.25 * c.b);
}

vec3 yCoCgToRgb(vec3 c) { return vec3(c.x + c.y - c.z, c.x + c.z, c.x - c.y - c.z); }

#if TAA_VALUE_COUNT(TAA_TONE_WEIGHT_VALUES) != 4
#error "toDomain, fromDomain, toneWeightedBlend: a taa.tonemap_weighting value without its branch"
#endif
#if TAA_VALUE_COUNT(TAA_COLOR_SPACE_VALUES) != 2
#error "isYCoCg: a taa.color_space value without its branch"
#endif

// inverse_luma and log run the whole resolve (neighbourhood box, rectification and
// blend) in a compressed domain, so that one bright sample cannot stretch the box and
// let a dark history through; Karis keeps the box linear and weights only the blend.
// (A blend alone in c/(1+luma) space equals Karis' weighted average exactly, so the
// domain is what tells inverse_luma apart.)
vec3 toDomain(TaaSettings s, vec3 c) {
  if (s.tonemap_weighting == TONE_WEIGHT_INVERSE_LUMA) {
    c = max(c, vec3(0.0));
    return c / (1.0 + luma(c));
  }
  if (s.tonemap_weighting == TONE_WEIGHT_LOG) return log(1.0 + max(c, vec3(0.0)));
  return c;  // TONE_WEIGHT_NONE, TONE_WEIGHT_KARIS: the box stays linear
}
vec3 fromDomain(TaaSettings s, vec3 d) {
  // c / (1 - luma) has a pole at luma 1: a box corner may lie beyond it; bound the result.
  if (s.tonemap_weighting == TONE_WEIGHT_INVERSE_LUMA) return d / max(1.0 - luma(d), 1.0 / kHalfMax);
  if (s.tonemap_weighting == TONE_WEIGHT_LOG) return exp(d) - 1.0;
  return d;  // TONE_WEIGHT_NONE, TONE_WEIGHT_KARIS
}

// Without rectification there is no box to shape, and a YCoCg round trip would only add
// rounding to the history (validation refuses taa.color_space there).
bool isYCoCg(TaaSettings s) { return s.color_space == COLOR_SPACE_YCOCG && s.rectify != RECTIFY_NONE; }
vec3 toWorking(TaaSettings s, vec3 rgb) {
  vec3 d = toDomain(s, rgb);
  return isYCoCg(s) ? rgbToYCoCg(d) : d;
}
vec3 fromWorking(TaaSettings s, vec3 w) { return fromDomain(s, isYCoCg(s) ? yCoCgToRgb(w) : w); }
float workingLuma(TaaSettings s, vec3 w) { return isYCoCg(s) ? w.x : luma(w); }

// Blends history toward current by alpha in the space the case chose. Karis weights
// each sample by 1/(1+luma) so a single bright sample cannot dominate; inverse-luma
// blends tonemapped colours and maps back; log blends log(1+c).
#if TAA_VALUE_COUNT(TAA_TONE_WEIGHT_VALUES) != 4
#error "toneWeightedBlend: a taa.tonemap_weighting value without its branch"
#endif
vec3 toneWeightedBlend(TaaSettings s, vec3 history, vec3 current, float alpha) {
  if (s.tonemap_weighting == TONE_WEIGHT_NONE) return mix(history, current, alpha);
  // The tone curves are defined for light. A YCoCg box's corners lie outside the RGB cube, so
  // a rectified history can carry negative components, with shrink_chroma or a variance box
  // even luma <= -1, where 1/(1+luma) changes sign or divides by zero and a dark pixel came
  // out as a 65504 firefly. The weighted blends see the non-negative part only.
  history = max(history, vec3(0.0));
  current = max(current, vec3(0.0));
  if (s.tonemap_weighting == TONE_WEIGHT_KARIS) {
    float wc = alpha / (1.0 + luma(current));
    float wh = (1.0 - alpha) / (1.0 + luma(history));
    return (current * wc + history * wh) / max(wc + wh, 1e-20);
  }
  // TONE_WEIGHT_INVERSE_LUMA, TONE_WEIGHT_LOG (`taa-harness coverage` found the plain blend
  // that used to follow unreachable for every value).
  return fromDomain(s, mix(toDomain(s, history), toDomain(s, current), alpha));
}

bool isFinite3(vec3 c) { return !any(isnan(c)) && !any(isinf(c)); }

// What may enter the history: finite, non-negative, representable in half floats.
vec3 boundColor(vec3 c) {
  c = mix(c, vec3(0.0), isnan(c));
  return clamp(c, vec3(0.0), vec3(kHalfMax));
}

// Rounds a bounded colour to the nearest half float (ties to even), so that storing it
// in an RGBA16F image is exact. Vulkan lets a half store round either way and lavapipe
// rounds toward zero; in the history's feedback loop that bias compounds (a blend step
// smaller than one ulp is always lost downward): a static scene at alpha 0.1 ended
// 0.16-0.27% darker than its reference after 24-32 frames. Exact in the half-normal
// range (above 6.1e-5); smaller values still lose their low bits in the store.
vec3 roundToHalf(vec3 c) {
  uvec3 u = floatBitsToUint(c);
  return uintBitsToFloat((u + 0x0FFFu + ((u >> 13) & 1u)) & ~0x1FFFu);
}

#endif
