// What a traced hit looks like to shading: position, normal, texture coordinates and
// their screen-space derivatives from ray differentials. The rays through the pixel
// one to the right and one down meet the hit triangle's plane at two more points
// (Akenine-Moller et al., "Texture level of detail strategies for real-time ray
// tracing"); their texture coordinates minus the hit's are the dUV/dx and dUV/dy the
// rasteriser takes from neighbouring fragments, so textureGrad picks the same mip.
#ifndef TAA_TRACE_SURFACE_GLSL
#define TAA_TRACE_SURFACE_GLSL

struct Surface {
  vec3 position;
  vec3 normal;  // unit, facing the ray (the raster flips back faces' normals too)
  vec2 uv;
  vec2 dUvDx, dUvDy;
  vec2 uv1;  // TEXCOORD_1 and its derivatives, for the textures that sample it
  vec2 dUv1Dx, dUv1Dy;
  vec4 color;  // interpolated vertex colour (meaningful where the mesh has COLOR_0)
  bool front;  // the ray meets the triangle's front face
};

vec2 interpolateUv(TraceShading s, float b1, float b2) {
  return s.uv01.xy * (1.0 - b1 - b2) + s.uv01.zw * b1 + s.uv2.xy * b2;
}

vec2 interpolateUv1(TraceShading s, float b1, float b2) {
  return s.uv1_01.xy * (1.0 - b1 - b2) + s.uv1_01.zw * b1 + s.uv1_2.xy * b2;
}

// Barycentrics (of v1, v2) where the line o + t d meets the triangle's plane,
// extended beyond the triangle's edges.
vec2 planeBarycentrics(TraceTriangle tri, vec3 o, vec3 d) {
  vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  vec3 ng = cross(e1, e2);
  float t = dot(tri.v0 - o, ng) / dot(d, ng);
  vec3 p = o + t * d - tri.v0;
  float d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
  float d20 = dot(p, e1), d21 = dot(p, e2);
  float denom = d00 * d11 - d01 * d01;
  return vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / denom;
}

struct CameraRay {
  vec3 origin;  // on the near plane
  vec3 dir;     // to the far plane: t in [0, 1] spans the raster's depth range
};

Surface surfaceAt(Hit h, CameraRay r, CameraRay rx, CameraRay ry) {
  TraceTriangle tri = triangles[h.tri];
  TraceShading s = shading[h.tri];
  float w = 1.0 - h.u - h.v;
  Surface f;
  f.position = tri.v0 * w + tri.v1 * h.u + tri.v2 * h.v;
  vec3 n = normalize(s.n0.xyz * w + s.n1.xyz * h.u + s.n2.xyz * h.v);
  // Front faces wind counter-clockwise on screen (the raster's VK_FRONT_FACE_COUNTER_CLOCKWISE
  // under a Y-flipped projection), so their geometric normal faces the ray.
  f.front = dot(cross(tri.v1 - tri.v0, tri.v2 - tri.v0), r.dir) < 0.0;
  f.normal = f.front ? n : -n;
  f.uv = interpolateUv(s, h.u, h.v);
  f.color = s.c0 * w + s.c1 * h.u + s.c2 * h.v;
  vec2 bx = planeBarycentrics(tri, rx.origin, rx.dir);
  vec2 by = planeBarycentrics(tri, ry.origin, ry.dir);
  f.dUvDx = interpolateUv(s, bx.x, bx.y) - f.uv;
  f.dUvDy = interpolateUv(s, by.x, by.y) - f.uv;
  f.uv1 = interpolateUv1(s, h.u, h.v);
  f.dUv1Dx = interpolateUv1(s, bx.x, bx.y) - f.uv1;
  f.dUv1Dy = interpolateUv1(s, by.x, by.y) - f.uv1;
  return f;
}

#endif
