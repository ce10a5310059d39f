// Directional + ambient Blinn-Phong, shared by forward shading and the deferred pass.
#ifndef TAA_LIGHTING_GLSL
#define TAA_LIGHTING_GLSL

vec3 shadeBlinnPhong(vec3 albedo, vec3 n, vec3 worldPos, FrameUniforms f) {
  vec3 l = f.lightDir.xyz;
  vec3 v = normalize(f.cameraPos.xyz - worldPos);
  float ndl = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), f.ambient.w) : 0.0;
  vec3 light = f.lightColor.rgb * f.lightDir.w;
  return albedo * (f.ambient.rgb + light * ndl) + light * (f.lightColor.w * spec);
}

// The same with the directional light scaled by `visibility` (lighting.shadows); a separate
// function so that unshadowed shading stays exactly the expression above.
vec3 shadeBlinnPhongShadowed(vec3 albedo, vec3 n, vec3 worldPos, FrameUniforms f, float visibility) {
  vec3 l = f.lightDir.xyz;
  vec3 v = normalize(f.cameraPos.xyz - worldPos);
  float ndl = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), f.ambient.w) : 0.0;
  vec3 light = f.lightColor.rgb * (f.lightDir.w * visibility);
  return albedo * (f.ambient.rgb + light * ndl) + light * (f.lightColor.w * spec);
}

// With an occlusion texture (glTF occlusionTexture): the ambient term times `occlusion`. Apart,
// so that the two functions above stay exactly the expressions they were.
vec3 shadeBlinnPhongOccluded(vec3 albedo, vec3 n, vec3 worldPos, FrameUniforms f, float visibility,
                             float occlusion) {
  vec3 l = f.lightDir.xyz;
  vec3 v = normalize(f.cameraPos.xyz - worldPos);
  float ndl = max(dot(n, l), 0.0);
  vec3 h = normalize(l + v);
  float spec = ndl > 0.0 ? pow(max(dot(n, h), 0.0), f.ambient.w) : 0.0;
  vec3 light = f.lightColor.rgb * (f.lightDir.w * visibility);
  return albedo * (f.ambient.rgb * occlusion + light * ndl) + light * (f.lightColor.w * spec);
}

// glTF's occlusion: 1 + strength * (red - 1), the same in the raster and the tracer.
float occlusionFactor(float red, float strength) { return 1.0 + strength * (red - 1.0); }

#endif
