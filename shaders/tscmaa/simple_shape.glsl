// CMAA's simple shapes: a pixel with edges on two, three or four sides (a corner, a
// spike, an isolated dot) that no Z shape explains is pulled toward the neighbours
// across those edges. The more sides, the more it stands out as aliasing, the more it
// is blended; `blurriness` scales every weight. Two opposite edges only (a one-pixel
// line) are kept sharp, as CMAA keeps thin features.
#ifndef TSCMAA_SIMPLE_SHAPE_GLSL
#define TSCMAA_SIMPLE_SHAPE_GLSL

// Weight of each neighbour relative to the pixel itself, by edge count (2, 3, 4).
float simpleShapeWeight(uint edges, float blurriness) {
  int n = bitCount(edges);
  if (n < 2 || edges == (TSCMAA_EDGE_LEFT | TSCMAA_EDGE_RIGHT) ||
      edges == (TSCMAA_EDGE_TOP | TSCMAA_EDGE_BOTTOM))
    return 0.0;
  return blurriness * (n == 2 ? 0.1 : n == 3 ? 0.2 : 0.25);
}

#endif
