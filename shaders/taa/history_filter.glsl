// Resampling the history at a fractional position. The bicubic filters reuse the
// hardware bilinear filter to fetch several texels per tap where they can.
#ifndef TAA_HISTORY_FILTER_GLSL
#define TAA_HISTORY_FILTER_GLSL

vec3 historyBilinear(sampler2D tex, vec2 uv) { return textureLod(tex, uv, 0.0).rgb; }

// Uniform cubic B-spline: all weights positive, so two bilinear fetches per axis
// give the exact 4x4 result (4 taps).
vec3 historyBSpline(sampler2D tex, vec2 uv, vec4 size) {
  vec2 p = uv * size.xy - 0.5;
  vec2 f = fract(p);
  vec2 base = floor(p) + 0.5;
  vec2 f2 = f * f, f3 = f2 * f;
  vec2 w0 = (1.0 - 3.0 * f + 3.0 * f2 - f3) / 6.0;
  vec2 w1 = (4.0 - 6.0 * f2 + 3.0 * f3) / 6.0;
  vec2 w2 = (1.0 + 3.0 * f + 3.0 * f2 - 3.0 * f3) / 6.0;
  vec2 w3 = f3 / 6.0;
  vec2 g0 = w0 + w1, g1 = w2 + w3;
  vec2 p0 = (base - 1.0 + w1 / g0) * size.zw;
  vec2 p1 = (base + 1.0 + w3 / g1) * size.zw;
  return g0.x * g0.y * textureLod(tex, vec2(p0.x, p0.y), 0.0).rgb +
         g1.x * g0.y * textureLod(tex, vec2(p1.x, p0.y), 0.0).rgb +
         g0.x * g1.y * textureLod(tex, vec2(p0.x, p1.y), 0.0).rgb +
         g1.x * g1.y * textureLod(tex, vec2(p1.x, p1.y), 0.0).rgb;
}

void catmullRomWeights(vec2 f, out vec2 w0, out vec2 w1, out vec2 w2, out vec2 w3) {
  w0 = f * (-0.5 + f * (1.0 - 0.5 * f));
  w1 = 1.0 + f * f * (-2.5 + 1.5 * f);
  w2 = f * (0.5 + f * (2.0 - 1.5 * f));
  w3 = f * f * (-0.5 + 0.5 * f);
}

// Catmull-Rom on 4x4 texels with 9 bilinear taps: the two middle texels of each
// axis share one tap (their weights are both positive).
vec3 historyCatmullRom9(sampler2D tex, vec2 uv, vec4 size) {
  vec2 p = uv * size.xy - 0.5;
  vec2 base = floor(p) + 0.5;
  vec2 w0, w1, w2, w3;
  catmullRomWeights(p - floor(p), w0, w1, w2, w3);
  vec2 w12 = w1 + w2;
  vec2 t0 = (base - 1.0) * size.zw;
  vec2 t12 = (base + w2 / w12) * size.zw;
  vec2 t3 = (base + 2.0) * size.zw;
  vec3 r = vec3(0.0);
  r += textureLod(tex, vec2(t0.x, t0.y), 0.0).rgb * (w0.x * w0.y);
  r += textureLod(tex, vec2(t12.x, t0.y), 0.0).rgb * (w12.x * w0.y);
  r += textureLod(tex, vec2(t3.x, t0.y), 0.0).rgb * (w3.x * w0.y);
  r += textureLod(tex, vec2(t0.x, t12.y), 0.0).rgb * (w0.x * w12.y);
  r += textureLod(tex, vec2(t12.x, t12.y), 0.0).rgb * (w12.x * w12.y);
  r += textureLod(tex, vec2(t3.x, t12.y), 0.0).rgb * (w3.x * w12.y);
  r += textureLod(tex, vec2(t0.x, t3.y), 0.0).rgb * (w0.x * w3.y);
  r += textureLod(tex, vec2(t12.x, t3.y), 0.0).rgb * (w12.x * w3.y);
  r += textureLod(tex, vec2(t3.x, t3.y), 0.0).rgb * (w3.x * w3.y);
  return r;
}

// The 5-tap approximation: the 9-tap layout without its four corner taps (their
// weights are the smallest), renormalised.
vec3 historyCatmullRom5(sampler2D tex, vec2 uv, vec4 size) {
  vec2 p = uv * size.xy - 0.5;
  vec2 base = floor(p) + 0.5;
  vec2 w0, w1, w2, w3;
  catmullRomWeights(p - floor(p), w0, w1, w2, w3);
  vec2 w12 = w1 + w2;
  vec2 t0 = (base - 1.0) * size.zw;
  vec2 t12 = (base + w2 / w12) * size.zw;
  vec2 t3 = (base + 2.0) * size.zw;
  float c = w12.x * w12.y, l = w0.x * w12.y, r = w3.x * w12.y, u = w12.x * w0.y, d = w12.x * w3.y;
  vec3 sum = textureLod(tex, vec2(t12.x, t12.y), 0.0).rgb * c + textureLod(tex, vec2(t0.x, t12.y), 0.0).rgb * l +
             textureLod(tex, vec2(t3.x, t12.y), 0.0).rgb * r + textureLod(tex, vec2(t12.x, t0.y), 0.0).rgb * u +
             textureLod(tex, vec2(t12.x, t3.y), 0.0).rgb * d;
  return sum / (c + l + r + u + d);
}

// Exact Catmull-Rom from 16 texel fetches; the reference the others approximate.
vec3 historyCatmullRom16(sampler2D tex, vec2 uv, vec4 size) {
  vec2 p = uv * size.xy - 0.5;
  ivec2 base = ivec2(floor(p));
  vec2 w[4];
  catmullRomWeights(p - floor(p), w[0], w[1], w[2], w[3]);
  ivec2 hi = ivec2(size.xy) - 1;
  vec3 r = vec3(0.0);
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      r += texelFetch(tex, clamp(base + ivec2(i - 1, j - 1), ivec2(0), hi), 0).rgb * (w[i].x * w[j].y);
  return r;
}

#if TAA_VALUE_COUNT(TAA_HISTORY_FILTER_VALUES) != 5
#error "sampleHistory: a taa.history_filter value without its branch"
#endif
vec3 sampleHistory(TaaSettings s, sampler2D tex, vec2 uv, vec4 size) {
  vec3 h;
  if (s.history_filter == HISTORY_FILTER_BSPLINE) h = historyBSpline(tex, uv, size);
  else if (s.history_filter == HISTORY_FILTER_CATMULL_ROM_9) h = historyCatmullRom9(tex, uv, size);
  else if (s.history_filter == HISTORY_FILTER_CATMULL_ROM_5) h = historyCatmullRom5(tex, uv, size);
  else if (s.history_filter == HISTORY_FILTER_CATMULL_ROM_16) h = historyCatmullRom16(tex, uv, size);
  else h = historyBilinear(tex, uv);  // HISTORY_FILTER_BILINEAR
  // Catmull-Rom's negative lobes can undershoot below zero next to bright edges.
  return max(h, vec3(0.0));
}

#endif
