// TSCMAA edge detection rules: CMAA's (Strugar, Intel 2014; its sample's CMAA.hlsl,
// EdgeDetectColorCalcDiff, Edges0PS and PruneNonDominantEdges), mirrored exactly by the
// CPU reference in tests/support/cpu_tscmaa.cpp: every expression that could be
// contracted into an FMA is `precise`, so the GPU mask and the CPU mask agree bit for bit.
#ifndef TSCMAA_EDGE_RULES_GLSL
#define TSCMAA_EDGE_RULES_GLSL

// Colour as displayed. CMAA detects edges on the 8-bit display-encoded back buffer, and
// TSCMAA's 1/22 threshold was tuned there; here the colour is still linear HDR, so it goes
// through this harness's own display transform (the PNGs' Reinhard c / (1 + c)), then the
// square root, CMAA 2's stand-in for the sRGB curve (ProcessColorForEdgeDetect), which
// unlike pow gives the CPU reference's bits on lavapipe.
vec3 edgeColor(vec3 c) {
  c = clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(65504.0));
  precise vec3 mapped = c / (1.0 + c);
  return sqrt(mapped);
}

// CMAA's edge value between two display-encoded colours: the Rec. 709 luma weights on
// the per-channel differences, less the threshold, kept in 4 bits rounded up so that
// any difference over the threshold is at least 1/15. Returned as the 4-bit count.
int edgeValue(vec3 a, vec3 b, float threshold) {
  vec3 d = abs(a - b);
  precise float diff = (0.2126 * d.r + 0.7152 * d.g) + 0.0722 * d.b;
  precise float above = clamp(diff - threshold, 0.0, 1.0);
  precise float scaled = above * 15.0 + 0.99;
  return int(scaled);
}

// CMAA's non-dominant edge removal. An edge is judged against the twelve edge values of
// its owner pixel's neighbourhood (`values[0]` is the edge itself): it stays if it
// reaches the mix of their mean and maximum set by `removal`. CMAA's sample sums the
// mean over its last group of four only (an assignment where an accumulation was meant:
// it still divides by twelve); the mean here is of all twelve.
bool edgeKept(int values[12], float removal) {
  if (values[0] == 0) return false;
  int maxValue = 0;
  int sum = 0;
  for (int i = 0; i < 12; ++i) {
    maxValue = max(maxValue, values[i]);
    sum += values[i];
  }
  // In units of 1/180 (twelve values of 1/15 each) the mean is the plain sum, and no
  // division is left to round differently on another device.
  precise float threshold = float(sum) * (1.0 - removal) + float(12 * maxValue) * removal;
  return float(12 * values[0]) >= threshold;
}

// A fixed 16-bit hash of the (side-by-side) pixel: the TAA share is the edge pixels
// whose hash is below share * 65536. A function of the pixel alone, never of the order
// in which threads append to the lists.
uint taaHash(uvec2 p) {
  uint h = (p.x * 0x8da6b343u) ^ (p.y * 0xd8163841u);
  h ^= h >> 16;
  h *= 0x7feb352du;
  h ^= h >> 15;
  h *= 0x846ca68bu;
  h ^= h >> 16;
  return h & 0xffffu;
}

uint packPixel(ivec2 p) { return uint(p.x) | (uint(p.y) << 16); }
ivec2 unpackPixel(uint v) { return ivec2(int(v & 0xffffu), int(v >> 16)); }

#endif
