// Every image a temporal resolve can sample, declared once for C++ and GLSL: the built-in
// resolve's samplers (taa_resolve.comp), its bind list, the bytes it reads a pixel and their
// check (renderer/passes/taa_resolve.cpp), the G-buffer images the plan allocates for it, and
// what a user's resolve may declare (taa_user.h is generated from these rows; renderer/user
// binds and reflects them) all come from TAA_RESOLVE_INPUTS. A setting's row in
// taa_settings.h says which inputs it reads.
//
// A new input is one row here (the next free binding of each side; both are checked unique
// at compile time in renderer/passes/resolve_inputs.h) and the code that samples it: in the
// built-in resolve it is a global sampler and a parameter of every TAA_INPUT_PARAMS function
// (the rejection chain, shaders/taa/rejection.glsl), for a user's shader a TAA_USE_* macro.
// (GLSL's preprocessor has no variadic macros, so every X macro takes all arguments.)
#ifndef TAA_RESOLVE_INPUTS_H
#define TAA_RESOLVE_INPUTS_H

// X(C++ enumerator, log name, GLSL name, binding, GLSL sampler type, format (VK_FORMAT_*),
//   filter (VK_FILTER_*), source, user GLSL name, user macro, user binding, user doc)
// source: COLOR the resolve's input colour (lit, or motion-blurred), OWN the stage's own
//   previous output (its history), GBUF(n) G-buffer image n (a GBufferNeeds member, which
//   the pass plan allocates when a read set contains the row).
// format: what the renderer allocates (UNDEFINED: the stage's own output's format).
// user macro: the TAA_USE_* a user's shader defines to get the input (TAA_USER_ALWAYS:
//   always declared); user binding -1: not offered to a user's shader.
// Rows are in the order the run log lists reads.
// clang-format off
#define TAA_RESOLVE_INPUTS(X)                                                                      \
  X(Color, "colour", colorTex, 1, sampler2D, R16G16B16A16_SFLOAT, NEAREST, COLOR,                  \
    taa_color, TAA_USER_ALWAYS, 1,                                                                 \
    "current frame's lit colour, linear HDR, render size")                         \
  X(History, "history", historyTex, 6, sampler2D, UNDEFINED, LINEAR, OWN,                          \
    taa_prev_output, TAA_USER_ALWAYS, 9,                                                           \
    "your previous frame's taa_output, output size")                     \
  X(Depth, "depth", depthTex, 2, sampler2D, D32_SFLOAT, NEAREST, GBUF(depth),                      \
    taa_depth, TAA_USE_DEPTH, 2, "depth, reversed Z (1 near, 0 far), render size")                 \
  X(Velocity, "velocity", velocityTex, 3, sampler2D, R16G16_SFLOAT, NEAREST, GBUF(velocity),       \
    taa_velocity, TAA_USE_VELOCITY, 3,                                                             \
    ".xy screen motion in render pixels: this pixel's content was at (pixel + 0.5 - velocity) "    \
    "last frame")                                                                                  \
  X(Ids, "ids", idsTex, 4, usampler2D, R32_UINT, NEAREST, GBUF(ids),                               \
    taa_ids, TAA_USE_IDS, 4, ".x object id, .y material id, .z 1 on movers (uint)")                \
  X(Normal, "normal", normalTex, 5, sampler2D, R16G16B16A16_SFLOAT, NEAREST, GBUF(normal),         \
    taa_normal, TAA_USE_NORMAL, 5, ".xyz world normal")                                            \
  X(PrevDepth, "prev_depth", prevDepthTex, 7, sampler2D, D32_SFLOAT, NEAREST, GBUF(prevDepth),     \
    taa_prev_depth, TAA_USE_PREV_DEPTH, 6, "last frame's depth")                                   \
  X(PrevNormal, "prev_normal", prevNormalTex, 8, sampler2D, R16G16B16A16_SFLOAT, NEAREST,          \
    GBUF(prevNormal), taa_prev_normal, TAA_USE_PREV_NORMAL, 8, "last frame's normals")             \
  X(PrevIds, "prev_ids", prevIdsTex, 9, usampler2D, R32_UINT, NEAREST, GBUF(prevIds),              \
    taa_prev_ids, TAA_USE_PREV_IDS, 7, "last frame's ids")                                         \
  X(PrevVelocity, "prev_velocity", prevVelocityTex, 10, sampler2D, R16G16_SFLOAT, NEAREST,         \
    GBUF(prevVelocity), taa_prev_velocity, TAA_USE_PREV_VELOCITY, 15,                              \
    "last frame's taa_velocity, as it was then (render pixels of last frame's render size)")      \
  X(ColorLinear, "colour_linear", colorLinearTex, 14, sampler2D, R16G16B16A16_SFLOAT, LINEAR,      \
    COLOR, taa_color_linear, TAA_USE_COLOR_LINEAR, 16,                                             \
    "taa_color again, to sample the current frame between pixel centres (GLSL only: HLSL "        \
    "samples taa_color through taa_linear_clamp)")
// clang-format on

// A user's resolve's bindings that are not inputs (taa_user.h): its frame uniforms, the
// output it writes and its own two history targets (read last frame's, write this frame's).
#define TAA_USER_BINDING_FRAME 0
#define TAA_USER_BINDING_OUTPUT 10
#define TAA_USER_BINDING_HISTORY0 11
#define TAA_USER_BINDING_HISTORY0_OUT 12
#define TAA_USER_BINDING_HISTORY1 13
#define TAA_USER_BINDING_HISTORY1_OUT 14

#ifndef __cplusplus
// The built-in resolve's samplers, and the same list as function parameters and arguments:
// `f(TaaSettings s TAA_INPUT_PARAMS)` is called `f(s TAA_INPUT_ARGS)`, so a new row reaches
// every such function without a change to its signature.
#define TAA_INPUT_SAMPLER(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  layout(binding = bind) uniform stype glsl;
#define TAA_INPUT_PARAM(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  , stype glsl
#define TAA_INPUT_ARG(cxx, log, glsl, bind, stype, fmt, filter, src, uname, umacro, ubind, udoc) \
  , glsl
#define TAA_INPUT_SAMPLERS TAA_RESOLVE_INPUTS(TAA_INPUT_SAMPLER)
#define TAA_INPUT_PARAMS TAA_RESOLVE_INPUTS(TAA_INPUT_PARAM)
#define TAA_INPUT_ARGS TAA_RESOLVE_INPUTS(TAA_INPUT_ARG)
#endif

#endif
