#version 450
// TSCMAA step 1: luma edge detection over the whole eye. Each pixel decides its four
// sides from the 3x3 luma around it (a side's edge is the same whichever of its two
// pixels decides it), writes the mask, and appends itself to the edge list and, if its
// hash falls in the TAA share, to the TAA list. The lists carry the group counts of the
// indirect passes over them, so those passes cost what the edge count costs.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "tscmaa/edge_rules.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std140, binding = TSCMAA_BINDING_UNIFORMS) uniform TscmaaBlock { TscmaaUniforms u; };
layout(binding = TSCMAA_BINDING_COLOR) uniform sampler2D colorTex;
layout(binding = TSCMAA_BINDING_MASK, r32ui) uniform writeonly uimage2D maskOut;
layout(std430, binding = TSCMAA_BINDING_EDGE_LIST) buffer EdgeList {
  EdgeListHeader edgeHeader;
  uint edgeEntries[];
};
layout(std430, binding = TSCMAA_BINDING_TAA_LIST) buffer TaaList {
  EdgeListHeader taaHeader;
  uint taaEntries[];
};

float gLuma[3][3];  // [dy + 1][dx + 1]; -1 outside the eye

// Edge across the vertical boundary right of (dx, dy), dx in -1..0, dy in -1..1.
float hEdge(int dx, int dy) {
  float a = gLuma[dy + 1][dx + 1], b = gLuma[dy + 1][dx + 2];
  return a < 0.0 || b < 0.0 ? 0.0 : abs(a - b);
}

// Edge across the horizontal boundary below (dx, dy), dx in -1..1, dy in -1..0.
float vEdge(int dx, int dy) {
  float a = gLuma[dy + 1][dx + 1], b = gLuma[dy + 2][dx + 1];
  return a < 0.0 || b < 0.0 ? 0.0 : abs(a - b);
}

float max6(float a, float b, float c, float d, float e, float f) {
  return max(max(max(a, b), max(c, d)), max(e, f));
}

bool kept(float e, float m) { return edgeKept(e, m, u.params.x, u.params.y); }

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(u.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      ivec2 q = p + ivec2(i, j);
      bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
      gLuma[j + 1][i + 1] = inside ? edgeLuma(texelFetch(colorTex, q, 0).rgb) : -1.0;
    }
  // Each side against the six edges that touch it: two in line, two at each end.
  float l = hEdge(-1, 0), t = vEdge(0, -1), r = hEdge(0, 0), b = vEdge(0, 0);
  float lt = hEdge(-1, -1), lb = hEdge(-1, 1), rt = hEdge(0, -1), rb = hEdge(0, 1);
  float tl = vEdge(-1, -1), tr = vEdge(1, -1), bl = vEdge(-1, 0), br = vEdge(1, 0);
  uint m = 0u;
  if (kept(l, max6(lt, lb, tl, t, bl, b))) m |= TSCMAA_EDGE_LEFT;
  if (kept(t, max6(tl, tr, lt, l, rt, r))) m |= TSCMAA_EDGE_TOP;
  if (kept(r, max6(rt, rb, t, tr, b, br))) m |= TSCMAA_EDGE_RIGHT;
  if (kept(b, max6(bl, br, l, lb, r, rb))) m |= TSCMAA_EDGE_BOTTOM;

  ivec2 g = p + ivec2(int(u.eye.x), 0);
  if (m != 0u && taaHash(uvec2(g)) < u.eye.y) m |= TSCMAA_TAA;
  imageStore(maskOut, g, uvec4(m));
  if (m == 0u) return;
  uint i = atomicAdd(edgeHeader.count, 1u);
  edgeEntries[i] = packPixel(p);
  if (i % TSCMAA_LIST_GROUP == 0u) atomicAdd(edgeHeader.groupsX, 1u);
  if ((m & TSCMAA_TAA) == 0u) return;
  i = atomicAdd(taaHeader.count, 1u);
  taaEntries[i] = packPixel(p);
  if (i % TSCMAA_LIST_GROUP == 0u) atomicAdd(taaHeader.groupsX, 1u);
}
