#version 450
#extension GL_GOOGLE_include_directive : require
#include "common/frame.glsl"

layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
layout(location = 2) in vec2 inUv;
layout(location = 3) in vec4 inColor;
layout(location = 4) in vec2 inUv1;

// Skinned and morphed vertices: where each was at frame - 1 (same space as inPosition),
// indexed like the deformed vertex buffer they are drawn from.
layout(std430, set = 0, binding = GBUF_BINDING_PREV_POSITIONS) readonly buffer PrevBlock { vec4 prevPositions[]; };

layout(location = 0) out vec3 outWorldPos;
layout(location = 1) out vec3 outNormal;
layout(location = 2) out vec2 outUv;
layout(location = 3) out vec4 outCurClip;   // un-jittered, for velocity
layout(location = 4) out vec4 outPrevClip;
layout(location = 5) out vec4 outColor;
layout(location = 6) out vec2 outUv1;
// The draw's instance for the fragment shader (gl_InstanceIndex counts from firstInstance).
layout(location = 7) flat out uint outInstance;

void main() {
  InstanceData inst = instances[gl_InstanceIndex];
  outInstance = uint(gl_InstanceIndex);
  vec4 world = inst.model * vec4(inPosition, 1.0);
  vec3 prevPosition = inst.ids.z != 0u ? prevPositions[gl_VertexIndex].xyz : inPosition;
  vec4 prevWorld = inst.prevModel * vec4(prevPosition, 1.0);
  outWorldPos = world.xyz;
  outNormal = mat3(inst.normalMatrix) * inNormal;
  outUv = inUv;
  outUv1 = inUv1;
  outColor = inColor;
  outCurClip = frame.viewProjNoJitter * world;
  outPrevClip = frame.prevViewProjNoJitter * prevWorld;
  gl_Position = frame.viewProj * world;
}
