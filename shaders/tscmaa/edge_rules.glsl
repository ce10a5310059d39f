// TSCMAA edge detection rules, mirrored exactly by the CPU reference in
// tests/support/cpu_tscmaa.cpp: every expression that could be contracted into an FMA
// is `precise`, so the GPU mask and the CPU mask agree bit for bit.
#ifndef TSCMAA_EDGE_RULES_GLSL
#define TSCMAA_EDGE_RULES_GLSL

// Perceptual luma in [0, 1): the square root of the Reinhard-mapped Rec. 709 luminance.
// The seed's threshold (1/22) is meant for display-encoded values; the square root
// stands in for the display curve, Reinhard for the HDR range.
float edgeLuma(vec3 c) {
  c = clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(65504.0));
  precise float y = (0.2126 * c.r + 0.7152 * c.g) + 0.0722 * c.b;
  precise float mapped = y / (1.0 + y);
  return sqrt(mapped);
}

// Non-dominant edge removal: an edge of strength e loses `removal` times the amount by
// which the strongest edge touching it (m) is stronger, then must exceed the threshold.
// Texture detail beside a silhouette thus drops out, and with it the blur CMAA would
// spend on it; an edge as strong as its neighbours keeps the plain threshold test.
bool edgeKept(float e, float m, float threshold, float removal) {
  precise float lowered = e - removal * max(m - e, 0.0);
  return lowered > threshold;
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
