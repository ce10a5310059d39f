// The G-buffer pass's per-frame block and per-draw push constants.
#ifndef TAA_FRAME_GLSL
#define TAA_FRAME_GLSL
#extension GL_GOOGLE_include_directive : require
#include "common/shared.h"

layout(std140, set = 0, binding = GBUF_BINDING_FRAME) uniform FrameBlock { FrameUniforms frame; };
layout(std430, set = 0, binding = GBUF_BINDING_INSTANCES) readonly buffer InstanceBlock { InstanceData instances[]; };
layout(push_constant) uniform PushBlock { DrawPush draw; };

#endif
