// Tangent-space normal mapping (glTF normalTexture) without stored tangents: the tangent
// frame comes per pixel from the screen derivatives of position and UV (the cotangent
// frame of C. Schueler, "Normal Mapping without Precomputed Tangents", ShaderX5, 2006).
// glTF's TANGENT attribute is not read and MikkTSpace is not available in Debian, so
// assets baked against MikkTSpace tangents can differ slightly where their UVs are skewed.
#ifndef TAA_NORMAL_MAP_GLSL
#define TAA_NORMAL_MAP_GLSL

// n: the unit surface normal (already facing the viewer); texel: the normal texture's RGB;
// scale: material.normal_strength times the texture's own scale (glTF: x and y scaled).
vec3 perturbNormal(vec3 n, vec3 dpdx, vec3 dpdy, vec2 duvdx, vec2 duvdy, vec3 texel, float scale) {
  vec3 t = texel * 2.0 - 1.0;
  t.xy *= scale;
  // Solve for the directions in which u and v grow, in the surface's plane. The solution is
  // divided by n . (dpdx x dpdy); only its sign matters before normalising, and it is
  // negative here (Vulkan's y points down the screen), positive in Schueler's OpenGL setting.
  vec3 dp2perp = cross(dpdy, n);
  vec3 dp1perp = cross(n, dpdx);
  float orientation = dot(n, cross(dpdx, dpdy)) < 0.0 ? -1.0 : 1.0;
  vec3 dpdu = (dp2perp * duvdx.x + dp1perp * duvdy.x) * orientation;
  vec3 dpdv = (dp2perp * duvdx.y + dp1perp * duvdy.y) * orientation;
  float len2 = max(dot(dpdu, dpdu), dot(dpdv, dpdv));
  if (!(len2 > 0.0)) return n;  // UVs that do not vary: no frame, keep the surface normal
  float inv = inversesqrt(len2);
  // glTF's +Y points to the image's top, where v decreases.
  vec3 m = dpdu * (inv * t.x) - dpdv * (inv * t.y) + n * t.z;
  float len = length(m);
  return len > 0.0 ? m / len : n;
}

#endif
