// CMAA's long-edge step: a run of pixels sharing an edge on the same side is a segment
// of a staircase. When its two ends step in opposite directions (a Z shape) the edge
// it approximates is the line through the midpoints of the two steps, and each pixel of
// the segment takes the colour across the edge in proportion to the area that line
// gives it (MLAA's coverage). U shapes, lone ends and runs longer than kMaxZRun are
// left alone: that restraint is what makes the anti-aliasing conservative.
// Needs: uint maskAt(ivec2 eyePixel) -> TSCMAA_EDGES bits, 0 outside the eye.
#ifndef TSCMAA_ZSHAPE_GLSL
#define TSCMAA_ZSHAPE_GLSL

const int kMaxZRun = 32;

uint sideBit(ivec2 dir) {
  if (dir.x < 0) return TSCMAA_EDGE_LEFT;
  if (dir.x > 0) return TSCMAA_EDGE_RIGHT;
  return dir.y < 0 ? TSCMAA_EDGE_TOP : TSCMAA_EDGE_BOTTOM;
}

// Where the line sits at a segment end, across the edge: +0.5 when the step there lies
// on the segment's own side (the line dips half a pixel into this row), -0.5 on the
// neighbour's side, 0 when there is no step or steps on both sides (not a Z end).
float endOffset(ivec2 last, ivec2 outward, ivec2 across) {
  uint bit = sideBit(outward);
  bool own = (maskAt(last) & bit) != 0u;
  bool other = (maskAt(last + across) & bit) != 0u;
  if (own == other) return 0.0;
  return own ? 0.5 : -0.5;
}

// Pixels beyond p along `along` that still carry `bit`; -1 when the run reaches the limit.
int runLength(ivec2 p, ivec2 along, uint bit) {
  for (int k = 1; k <= kMaxZRun; ++k)
    if ((maskAt(p + k * along) & bit) == 0u) return k - 1;
  return -1;
}

// Integral over [0, 1] of max(d, 0) for d linear from d0 to d1.
float positiveArea(float d0, float d1) {
  if (d0 >= 0.0 && d1 >= 0.0) return 0.5 * (d0 + d1);
  if (d0 <= 0.0 && d1 <= 0.0) return 0.0;
  float top = max(d0, d1);
  return 0.5 * top * top / abs(d0 - d1);
}

// The share of p that the colour across its side `across` covers, by the Z shape the
// edge on that side belongs to; 0 when it belongs to none. p and its neighbour find the
// same segment and get complementary shares.
float zCoverage(ivec2 p, ivec2 across) {
  ivec2 along = ivec2(abs(across.y), abs(across.x));
  uint bit = sideBit(across);
  int back = runLength(p, -along, bit), ahead = runLength(p, along, bit);
  if (back < 0 || ahead < 0) return 0.0;
  int n = back + ahead + 1;
  if (n > kMaxZRun) return 0.0;  // every pixel of a run decides alike
  float start = endOffset(p - back * along, -along, across);
  float end = endOffset(p + ahead * along, along, across);
  if (start == 0.0 || end != -start) return 0.0;
  // The line runs from `start` at the segment's beginning to `end` at its finish.
  float d0 = start * (1.0 - 2.0 * float(back) / float(n));
  float d1 = start * (1.0 - 2.0 * float(back + 1) / float(n));
  return positiveArea(d0, d1);
}

#endif
