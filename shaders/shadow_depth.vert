#version 450
// Shadow casters: the scene's vertices in one cascade's light clip space.
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inUv1;

layout(std430, set = 0, binding = SHADOW_BINDING_INSTANCES) readonly buffer InstanceBlock { InstanceData instances[]; };
layout(push_constant) uniform PushBlock { ShadowPush shadow; };

layout(location = 0) out vec2 outUv;
layout(location = 1) out float outAlpha;

void main() {
  InstanceData inst = instances[gl_InstanceIndex];
  outUv = (shadow.maps & MATERIAL_BASE_UV1) != 0u ? inUv1 : inUv;  // the base colour's set
  outAlpha = inst.ids.w != 0u ? inColor.a : 1.0;  // COLOR_0 alpha, as gbuffer.frag applies it
  gl_Position = shadow.lightViewProj * (inst.model * vec4(inPosition, 1.0));
}
