#version 450
// FXAA, the quality algorithm of Lottes' FXAA 3.11, on the output image:
//  1. luma = sqrt(Rec.601 luma) of the tonemapped colour c / (1 + c) (FXAA wants a
//     perceptual [0,1] luma);
//  2. local contrast of the cross: pixels whose range is below
//     max(edge threshold min, max luma * edge threshold) are left bit-exact;
//  3. edge direction from the 3x3 second derivatives (horizontal vs vertical span),
//     and the side (the neighbour across the edge with the larger gradient);
//  4. search both ways along the edge, half a pixel towards that side, in steps of
//     quality preset 39 (1,1,1,1,1,1.5,2,2,2,2,4,8 px), until the bilinear luma
//     leaves the edge's mean by a quarter of its gradient;
//  5. the nearer end gives the offset 0.5 - distance / span length, kept only when
//     that end runs the expected way (the "good span"); sub-pixel aliasing sets a
//     floor from the 3x3 lowpass contrast (smoothstep, squared, times subpix);
//  6. the output is the bilinear colour at the pixel moved by that offset across the
//     edge, blended in the tonemapped space and mapped back.
// Every tap is scrubbed (NaN -> 0, Inf -> half max) before it is used.
// Masked (adaptive mode): only pixels the segmentation marks ADAPTIVE_MASK_FXAA are
// filtered; every other pixel is copied bit for bit. The output has no format
// qualifier so that it can be the history's format (RGBA16F or RGBA32F).
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"
#include "post/post_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(constant_id = FXAA_SPEC_MASKED) const bool kMasked = false;

layout(push_constant) uniform Push { PostPush pc; };
layout(binding = POST_BINDING_INPUT) uniform sampler2D inputTex;
layout(binding = POST_BINDING_OUTPUT) uniform writeonly image2D outImage;
layout(binding = POST_BINDING_MASK) uniform usampler2D maskTex;

const int kSearchSteps = 12;
const float kStep[kSearchSteps] =
    float[](1.0, 1.0, 1.0, 1.0, 1.0, 1.5, 2.0, 2.0, 2.0, 2.0, 4.0, 8.0);

ivec2 gHi;

vec3 tonemappedAt(ivec2 q) {
  return tonemap(scrub(texelFetch(inputTex, clamp(q, ivec2(0), gHi), 0).rgb));
}
float lumaAt(ivec2 q) { return sqrt(dot(tonemappedAt(q), vec3(0.299, 0.587, 0.114))); }

// Bilinear interpolation at `pos` (pixel units, centres at +0.5), done by hand so
// that each texel is scrubbed first: a hardware-filtered NaN would poison the blend.
float lumaBilinear(vec2 pos) {
  vec2 f = pos - 0.5;
  ivec2 i = ivec2(floor(f));
  vec2 t = f - floor(f);
  return mix(mix(lumaAt(i), lumaAt(i + ivec2(1, 0)), t.x),
             mix(lumaAt(i + ivec2(0, 1)), lumaAt(i + ivec2(1, 1)), t.x), t.y);
}

vec3 tonemappedBilinear(vec2 pos) {
  vec2 f = pos - 0.5;
  ivec2 i = ivec2(floor(f));
  vec2 t = f - floor(f);
  return mix(mix(tonemappedAt(i), tonemappedAt(i + ivec2(1, 0)), t.x),
             mix(tonemappedAt(i + ivec2(0, 1)), tonemappedAt(i + ivec2(1, 1)), t.x), t.y);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = ivec2(pc.size.xy);
  if (any(greaterThanEqual(p, size))) return;
  gHi = size - 1;
  vec4 original = texelFetch(inputTex, p, 0);
  if (kMasked && texelFetch(maskTex, p, 0).r != ADAPTIVE_MASK_FXAA) {
    imageStore(outImage, p, original);
    return;
  }

  // y grows downwards: N is the row above.
  float lM = lumaAt(p);
  float lN = lumaAt(p + ivec2(0, -1)), lS = lumaAt(p + ivec2(0, 1));
  float lW = lumaAt(p + ivec2(-1, 0)), lE = lumaAt(p + ivec2(1, 0));
  float rangeMax = max(max(max(lN, lS), max(lW, lE)), lM);
  float rangeMin = min(min(min(lN, lS), min(lW, lE)), lM);
  float range = rangeMax - rangeMin;
  if (range < max(pc.params.y, rangeMax * pc.params.x)) {
    imageStore(outImage, p, original);
    return;
  }

  float lNW = lumaAt(p + ivec2(-1, -1)), lNE = lumaAt(p + ivec2(1, -1));
  float lSW = lumaAt(p + ivec2(-1, 1)), lSE = lumaAt(p + ivec2(1, 1));

  // Vertical second derivatives (columns W, M, E) measure a horizontal edge.
  float edgeHorz =
      abs(lNW + lSW - 2.0 * lW) + 2.0 * abs(lN + lS - 2.0 * lM) + abs(lNE + lSE - 2.0 * lE);
  float edgeVert =
      abs(lNW + lNE - 2.0 * lN) + 2.0 * abs(lW + lE - 2.0 * lM) + abs(lSW + lSE - 2.0 * lS);
  bool horzSpan = edgeHorz >= edgeVert;

  // Sub-pixel aliasing: how far the pixel stands out of its 3x3 lowpass.
  float lowpass = (2.0 * (lN + lS + lW + lE) + (lNW + lNE + lSW + lSE)) / 12.0;
  float subC = clamp(abs(lowpass - lM) / range, 0.0, 1.0);
  float subF = (3.0 - 2.0 * subC) * subC * subC;
  float subpixOffset = subF * subF * pc.params.z;

  float lNeg = horzSpan ? lN : lW;
  float lPos = horzSpan ? lS : lE;
  float gNeg = abs(lNeg - lM), gPos = abs(lPos - lM);
  bool towardsNeg = gNeg >= gPos;
  float side = towardsNeg ? -1.0 : 1.0;
  float edgeLuma = 0.5 * (lM + (towardsNeg ? lNeg : lPos));
  float gradientScaled = 0.25 * max(gNeg, gPos);
  bool centreBelowEdge = lM < edgeLuma;

  vec2 along = horzSpan ? vec2(1.0, 0.0) : vec2(0.0, 1.0);
  vec2 across = horzSpan ? vec2(0.0, 1.0) : vec2(1.0, 0.0);
  vec2 centre = vec2(p) + 0.5;
  vec2 posB = centre + across * (0.5 * side);
  vec2 posN = posB - along * kStep[0], posP = posB + along * kStep[0];
  float endN = lumaBilinear(posN) - edgeLuma, endP = lumaBilinear(posP) - edgeLuma;
  bool doneN = abs(endN) >= gradientScaled, doneP = abs(endP) >= gradientScaled;
  for (int i = 1; i < kSearchSteps && !(doneN && doneP); ++i) {
    if (!doneN) {
      posN -= along * kStep[i];
      endN = lumaBilinear(posN) - edgeLuma;
      doneN = abs(endN) >= gradientScaled;
    }
    if (!doneP) {
      posP += along * kStep[i];
      endP = lumaBilinear(posP) - edgeLuma;
      doneP = abs(endP) >= gradientScaled;
    }
  }
  // An end not found within the search is assumed one more (largest) step away.
  if (!doneN) posN -= along * kStep[kSearchSteps - 1];
  if (!doneP) posP += along * kStep[kSearchSteps - 1];

  float dstN = dot(centre - posN, along), dstP = dot(posP - centre, along);
  bool nearerN = dstN < dstP;
  // The span is good when the luma at its nearer end lies on the other side of the
  // edge mean from the centre: the edge really turns there.
  bool goodSpan = ((nearerN ? endN : endP) < 0.0) != centreBelowEdge;
  float edgeOffset = goodSpan ? 0.5 - min(dstN, dstP) / (dstN + dstP) : 0.0;
  float offset = max(edgeOffset, subpixOffset);
  if (offset <= 0.0) {
    imageStore(outImage, p, original);
    return;
  }
  vec3 t = tonemappedBilinear(centre + across * (side * offset));
  imageStore(outImage, p, vec4(untonemap(t), original.a));
}
