// taa_user.h: the interface between taa-harness and your own temporal resolve.
//
// Write a GLSL compute shader, `#include "taa_user.h"`, and point a case at it with
// `"taa": {"shader": "my_resolve.comp"}`. The harness compiles it at run time (glslang,
// Vulkan 1.2, SPIR-V 1.5) and runs it once per frame, one invocation per output pixel,
// right after the G-buffer, in place of the built-in resolve. docs/user-taa.md has a
// complete example.
//
// Always declared:
//   taa_color        current frame's lit colour, linear HDR, render size (point sampler)
//   taa_prev_output  your previous frame's taa_output, output size (bilinear, clamp to edge)
//   taa_output       write this frame's result here (rgba16f, output size); it is what the
//                    harness compares, and next frame's taa_prev_output
//   the TaaUserFrame uniform block below
//
// Declared when you define the macro BEFORE the #include (the harness then allocates and
// fills that G-buffer target; a target nobody reads is never rendered):
//   TAA_USE_DEPTH        taa_depth       depth, reversed Z (1 near, 0 far), render size
//   TAA_USE_VELOCITY     taa_velocity    .xy screen motion in render pixels: this pixel's
//                                        content was at (pixel + 0.5 - velocity) last frame
//   TAA_USE_IDS          taa_ids         .x object id, .y material id, .z 1 on movers (uint)
//   TAA_USE_NORMAL       taa_normal      .xyz world normal
//   TAA_USE_PREV_DEPTH   taa_prev_depth  last frame's depth
//   TAA_USE_PREV_IDS     taa_prev_ids    last frame's ids
//   TAA_USE_PREV_NORMAL  taa_prev_normal last frame's normals
//
// Your own history targets (output size, ping-ponged by the harness, zero on the first
// frame): define TAA_HISTORY0_FORMAT (and TAA_HISTORY1_FORMAT) as one of rgba16f, rgba32f,
// rg16f, rg32f, r16f, r32f; read last frame's with taa_history0 (a bilinear sampler2D)
// and write this frame's with imageStore(taa_history0_out, pixel, value).
//
// Parameters: any `layout(constant_id = N) const float name = default;` (bool, int, uint
// or float; N from 0 to 99) can be set from the case with
// "shader_params": [{"name": "name", "value": 1.5}]; a name the shader does not declare,
// or a value of the wrong type, is refused when the case loads.
//
// History validity: taa_frame.info.y is 0 on a frame whose history must not be used (the
// first frame, a camera cut, a scripted reset); write the current colour there.
#ifndef TAA_USER_H
#define TAA_USER_H

#define TAA_USER_VERSION 1

// Workgroup of 8x8 invocations; one invocation per output pixel (some may lie outside it).
layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

layout(std140, set = 0, binding = 0) uniform TaaUserFrame {
  mat4 viewProj;      // this frame's un-jittered view-projection
  mat4 invViewProj;   // its inverse: NDC (x, y, depth) -> world
  mat4 prevViewProj;  // last frame's view-projection
  vec4 renderSize;    // xy: render size in pixels, zw: 1 / xy
  vec4 outputSize;    // xy: output size in pixels (taa_output), zw: 1 / xy
  vec4 jitter;        // xy: this frame's jitter in render pixels, zw: last frame's
  vec4 camera;        // x: near plane, y: far plane
  uvec4 info;         // x: frame index, y: 1 when history is valid, 0 on a reset
} taa_frame;

layout(set = 0, binding = 1) uniform sampler2D taa_color;
#ifdef TAA_USE_DEPTH
layout(set = 0, binding = 2) uniform sampler2D taa_depth;
#endif
#ifdef TAA_USE_VELOCITY
layout(set = 0, binding = 3) uniform sampler2D taa_velocity;
#endif
#ifdef TAA_USE_IDS
layout(set = 0, binding = 4) uniform usampler2D taa_ids;
#endif
#ifdef TAA_USE_NORMAL
layout(set = 0, binding = 5) uniform sampler2D taa_normal;
#endif
#ifdef TAA_USE_PREV_DEPTH
layout(set = 0, binding = 6) uniform sampler2D taa_prev_depth;
#endif
#ifdef TAA_USE_PREV_IDS
layout(set = 0, binding = 7) uniform usampler2D taa_prev_ids;
#endif
#ifdef TAA_USE_PREV_NORMAL
layout(set = 0, binding = 8) uniform sampler2D taa_prev_normal;
#endif
layout(set = 0, binding = 9) uniform sampler2D taa_prev_output;
layout(set = 0, binding = 10, rgba16f) uniform writeonly image2D taa_output;
#ifdef TAA_HISTORY0_FORMAT
layout(set = 0, binding = 11) uniform sampler2D taa_history0;
layout(set = 0, binding = 12, TAA_HISTORY0_FORMAT) uniform writeonly image2D taa_history0_out;
#endif
#ifdef TAA_HISTORY1_FORMAT
layout(set = 0, binding = 13) uniform sampler2D taa_history1;
layout(set = 0, binding = 14, TAA_HISTORY1_FORMAT) uniform writeonly image2D taa_history1_out;
#endif

// This invocation's output pixel; false for invocations past the edge (return at once).
bool taa_pixel(out ivec2 pixel) {
  pixel = ivec2(gl_GlobalInvocationID.xy);
  return all(lessThan(pixel, ivec2(taa_frame.outputSize.xy)));
}

bool taa_has_history() { return taa_frame.info.y != 0u; }

// The render pixel under output pixel p (the same pixel unless the case upsamples).
ivec2 taa_render_pixel(ivec2 p) {
  return ivec2((vec2(p) + 0.5) * taa_frame.renderSize.xy * taa_frame.outputSize.zw);
}

// The current colour at render pixel p, clamped to the render area.
vec3 taa_color_at(ivec2 p) {
  return texelFetch(taa_color, clamp(p, ivec2(0), ivec2(taa_frame.renderSize.xy) - 1), 0).rgb;
}

#endif  // TAA_USER_H
