// Directional-light visibility from the cascaded shadow atlas (renderer/frame/shadow_cascades.h):
// the cascade whose view-depth slice holds the point, the point pushed along its normal by
// about a texel and a half, then 3x3 taps one texel apart through a bilinear comparison
// sampler (each tap the lit share of a 2x2 footprint: a 4x4-texel PCF kernel). Past the last
// cascade everything is lit. Cascades switch hard at their splits (no blend band).
#ifndef TAA_SHADOW_GLSL
#define TAA_SHADOW_GLSL

float shadowVisibility(sampler2DShadow atlas, FrameUniforms f, vec3 worldPos, vec3 n) {
  int count = int(f.shadowForward.w);
  float viewDepth = dot(worldPos - f.shadowOrigin.xyz, f.shadowForward.xyz);
  int c = 0;
  while (c < count && viewDepth > f.shadowSplits[c]) ++c;
  if (c >= count) return 1.0;
  vec3 p = worldPos + n * f.shadowNormalOffset[c];
  vec3 s = (f.shadowMatrix[c] * vec4(p, 1.0)).xyz;
  // Keep the kernel inside the cascade's own tile of the atlas.
  vec2 texel = f.shadowAtlas.xy;
  float tileLo = float(c) * f.shadowAtlas.z;
  vec2 uv = vec2(clamp(s.x, tileLo + 2.0 * texel.x, tileLo + f.shadowAtlas.z - 2.0 * texel.x),
                 clamp(s.y, 2.0 * texel.y, 1.0 - 2.0 * texel.y));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) lit += texture(atlas, vec3(uv + vec2(x, y) * texel, s.z));
  return lit * (1.0 / 9.0);
}

#endif
