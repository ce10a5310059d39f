#version 450
// TSCMAA step 1: CMAA's edge detection over the whole eye. Each pixel finds its four
// sides from the 5x5 colours around it, judging each side as its owner pixel does (so a
// side's edge is the same whichever of its two pixels asks), writes the mask, and
// appends itself to the edge list and, if its hash falls in the TAA share, to the TAA
// list. The lists carry the group counts of the indirect passes over them, so those
// passes cost what the edge count costs.
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

// Display-encoded colours of the 5x5 pixels around this one ([dy + 2][dx + 2]), and
// whether each lies inside the eye.
vec3 gColor[5][5];
bool gInside[5][5];

// The 4-bit value of the edge right of (dx, dy), or below it; 0 where the pixel across
// lies outside the grid or the eye (the image border is not an edge).
int rightEdge(int dx, int dy) {
  if (dx >= 2 || !gInside[dy + 2][dx + 2] || !gInside[dy + 2][dx + 3]) return 0;
  return edgeValue(gColor[dy + 2][dx + 2], gColor[dy + 2][dx + 3], u.params.x);
}
int bottomEdge(int dx, int dy) {
  if (dy >= 2 || !gInside[dy + 2][dx + 2] || !gInside[dy + 3][dx + 2]) return 0;
  return edgeValue(gColor[dy + 2][dx + 2], gColor[dy + 3][dx + 2], u.params.x);
}

// CMAA decides each edge once, at its owner: the pixel left of a vertical edge, above a
// horizontal one. The twelve values it weighs are the owner's right and bottom edges,
// those of its four neighbours, the bottom edge of its upper-right and the right edge of
// its lower-left neighbour; the edge judged comes first.
bool ownerKeeps(int dx, int dy, bool right) {
  int r = rightEdge(dx, dy), b = bottomEdge(dx, dy);
  int v[12] = int[12](right ? r : b, right ? b : r, rightEdge(dx + 1, dy), bottomEdge(dx + 1, dy),
                      rightEdge(dx, dy + 1), bottomEdge(dx, dy + 1), rightEdge(dx - 1, dy),
                      bottomEdge(dx - 1, dy), rightEdge(dx, dy - 1), bottomEdge(dx, dy - 1),
                      bottomEdge(dx + 1, dy - 1), rightEdge(dx - 1, dy + 1));
  return edgeKept(v, u.params.y);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(u.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  for (int j = -2; j <= 2; ++j)
    for (int i = -2; i <= 2; ++i) {
      ivec2 q = p + ivec2(i, j);
      bool inside = all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, size));
      gInside[j + 2][i + 2] = inside;
      gColor[j + 2][i + 2] = inside ? edgeColor(texelFetch(colorTex, q, 0).rgb) : vec3(0.0);
    }
  uint m = 0u;
  if (ownerKeeps(-1, 0, true)) m |= TSCMAA_EDGE_LEFT;
  if (ownerKeeps(0, -1, false)) m |= TSCMAA_EDGE_TOP;
  if (ownerKeeps(0, 0, true)) m |= TSCMAA_EDGE_RIGHT;
  if (ownerKeeps(0, 0, false)) m |= TSCMAA_EDGE_BOTTOM;

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
