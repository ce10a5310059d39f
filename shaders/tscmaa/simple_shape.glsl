// CMAA's simple shapes: a pixel with edges on two, three or four sides (a corner, a
// spike, an isolated dot) that no Z shape explains is pulled toward the neighbours
// across those edges. Two opposite edges only (a one-pixel line) are kept sharp, as
// CMAA keeps thin features.
#ifndef TSCMAA_SIMPLE_SHAPE_GLSL
#define TSCMAA_SIMPLE_SHAPE_GLSL

// TSCMAA's default blurriness, at which the weights are CMAA's own.
#define TSCMAA_DEFAULT_BLURRINESS 0.7

// Weight of each neighbour relative to the pixel itself, by edge count: CMAA's sample
// (ProcessAndApplyPS) uses 0.08 for a corner, 0.11 for three sides and 0.05 for four,
// the last low because a pixel walled in on all sides is as likely a feature as an
// artefact. TSCMAA's blurriness knob scales them; how TSCMAA applied it is not
// published (its code sample is gone), so the scale is relative to its default.
float simpleShapeWeight(uint edges, float blurriness) {
  int n = bitCount(edges);
  if (n < 2 || edges == (TSCMAA_EDGE_LEFT | TSCMAA_EDGE_RIGHT) ||
      edges == (TSCMAA_EDGE_TOP | TSCMAA_EDGE_BOTTOM))
    return 0.0;
  float cmaa = n == 2 ? 0.08 : n == 3 ? 0.11 : 0.05;
  return cmaa * (blurriness / TSCMAA_DEFAULT_BLURRINESS);
}

#endif
