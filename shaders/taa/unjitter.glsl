// Seed 000's "unjitter" debugging aids: the colour at a pixel's centre in an unjittered
// frame, rebuilt from the jittered samples around it.
#ifndef TAA_UNJITTER_GLSL
#define TAA_UNJITTER_GLSL

// A jittered frame shows at pixel k the scene at k + 0.5 - jitter (render pixels; the image
// moves by the jitter), so the centre of pixel p lies at sample coordinate p + jitter, between
// four samples: their bilinear mix. Off the image the edge samples repeat.
vec3 unjitteredColor(sampler2D colorTex, ivec2 p, vec2 jitter, ivec2 hi) {
  vec2 t = vec2(p) + jitter;
  ivec2 base = ivec2(floor(t));
  vec2 f = t - vec2(base);
  vec3 c00 = texelFetch(colorTex, clamp(base, ivec2(0), hi), 0).rgb;
  vec3 c10 = texelFetch(colorTex, clamp(base + ivec2(1, 0), ivec2(0), hi), 0).rgb;
  vec3 c01 = texelFetch(colorTex, clamp(base + ivec2(0, 1), ivec2(0), hi), 0).rgb;
  vec3 c11 = texelFetch(colorTex, clamp(base + ivec2(1, 1), ivec2(0), hi), 0).rgb;
  return mix(mix(c00, c10, f.x), mix(c01, c11, f.x), f.y);
}

#endif
