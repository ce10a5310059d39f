#version 450
// Alpha-tested casters (fences, foliage cards) cast the shape the G-buffer draws:
// the same base colour, factor and cutoff; everything else only writes depth.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(constant_id = GBUF_SPEC_LOD0_ALPHA) const bool kLod0Alpha = false;  // render.lod0 or lod0_alpha_test

layout(set = 0, binding = SHADOW_BINDING_TEXTURE) uniform sampler2D baseColorTexture;
layout(push_constant) uniform PushBlock { ShadowPush shadow; };

layout(location = 0) in vec2 inUv;
layout(location = 1) in float inAlpha;

void main() {
  if (shadow.alphaCutoff < 0.0) return;
  float texel = kLod0Alpha ? textureLod(baseColorTexture, inUv, 0.0).a : texture(baseColorTexture, inUv).a;
  float alpha = shadow.baseColor.a * texel * inAlpha;
  if (alpha < shadow.alphaCutoff) discard;
}
