// Every setting of the temporal resolve, declared once, for C++ and GLSL alike: its case
// key, type, default, range, the modes it applies to, the rule that makes it mean
// something, its documentation, and the specialization constant or uniform slot it
// drives. renderer/spec/taa_spec.h builds TaaSpec, the case reader/writer and
// `techniques --json` from these lists; renderer/passes/taa_resolve.cpp the
// specialization constants and uniform slots; shaders/taa_resolve.comp the constants
// and the TaaSettings struct the shader includes take. An enum's values are named
// constants on both sides (HISTORY_FILTER_CATMULL_ROM_5): a shader that names a value
// that does not exist fails to compile, and reordering a list changes nothing.
// (GLSL's preprocessor has no variadic macros, so every X macro takes all arguments.)
#ifndef TAA_SETTINGS_H
#define TAA_SETTINGS_H

// ---- Enumerations: X(C++ enumerator, GLSL constant, value, case-file name) ----
// Which shader path the resolve runs; renderer/spec/taa_modes.h maps modes to it.
#define TAA_RESOLVE_VALUES(X)                             \
  X(PassThrough, RESOLVE_PASS_THROUGH, 0, "pass_through") \
  X(Basic, RESOLVE_BASIC, 1, "basic")                     \
  X(Full, RESOLVE_FULL, 2, "full")

#define TAA_TONE_WEIGHT_VALUES(X)                             \
  X(None, TONE_WEIGHT_NONE, 0, "none")                        \
  X(Karis, TONE_WEIGHT_KARIS, 1, "karis")                     \
  X(InverseLuma, TONE_WEIGHT_INVERSE_LUMA, 2, "inverse_luma") \
  X(Log, TONE_WEIGHT_LOG, 3, "log")

#define TAA_USE_VELOCITY_VALUES(X)            \
  X(Off, USE_VELOCITY_OFF, 0, "off")          \
  X(Movers, USE_VELOCITY_MOVERS, 1, "movers") \
  X(All, USE_VELOCITY_ALL, 2, "all")

#define TAA_VELOCITY_SAMPLING_VALUES(X)                         \
  X(Pixel, VELOCITY_SAMPLING_PIXEL, 0, "pixel")                 \
  X(Longest3x3, VELOCITY_SAMPLING_LONGEST_3X3, 1, "longest3x3") \
  X(Closest3x3, VELOCITY_SAMPLING_CLOSEST_3X3, 2, "closest3x3")

#define TAA_HISTORY_FILTER_VALUES(X)                               \
  X(Bilinear, HISTORY_FILTER_BILINEAR, 0, "bilinear")              \
  X(BSpline, HISTORY_FILTER_BSPLINE, 1, "bspline")                 \
  X(CatmullRom9, HISTORY_FILTER_CATMULL_ROM_9, 2, "catmull_rom_9") \
  X(CatmullRom5, HISTORY_FILTER_CATMULL_ROM_5, 3, "catmull_rom_5") \
  X(CatmullRom16, HISTORY_FILTER_CATMULL_ROM_16, 4, "catmull_rom_16")

#define TAA_RECTIFY_VALUES(X)         \
  X(None, RECTIFY_NONE, 0, "none")    \
  X(Clamp, RECTIFY_CLAMP, 1, "clamp") \
  X(Clip, RECTIFY_CLIP, 2, "clip")

#define TAA_COLOR_SPACE_VALUES(X)   \
  X(Rgb, COLOR_SPACE_RGB, 0, "rgb") \
  X(YCoCg, COLOR_SPACE_YCOCG, 1, "ycocg")

#define TAA_HISTORY_FORMAT_VALUES(X)               \
  X(Rgba16f, HISTORY_FORMAT_RGBA16F, 0, "rgba16f") \
  X(Rgba32f, HISTORY_FORMAT_RGBA32F, 1, "rgba32f")

#define TAA_DEBUG_OUTPUT_VALUES(X)                                   \
  X(None, DEBUG_OUTPUT_NONE, 0, "none")                              \
  X(Velocity, DEBUG_OUTPUT_VELOCITY, 1, "velocity")                  \
  X(Rejection, DEBUG_OUTPUT_REJECTION, 2, "rejection")               \
  X(ClampDistance, DEBUG_OUTPUT_CLAMP_DISTANCE, 3, "clamp_distance") \
  X(Segmentation, DEBUG_OUTPUT_SEGMENTATION, 4, "segmentation")

// ---- Settings (taa.*), in case-file order after taa.mode ----
// E(key, C++ type, values list, default, specialization id, GLSL constant, modes, reads, rule,
//   rule text, doc, impl): an enum setting
// B(key, default, specialization id, GLSL constant, modes, reads, rule, rule text, doc, impl): a
//   switch
// F(key, default, lo, hi, uniform slot, GLSL slot name, modes, rule, rule text, doc, impl): a float
// modes: the taa.mode values in which the key may be set (kBlending, kReprojecting,
// kFullOnly in renderer/spec/taa_modes.h); a setting outside them takes its
// default, and the specialization constant gets 0 where the resolve path has no use for
// it. rule: a predicate of the effective settings that must hold for the key to mean
// something, as a C++ lambda (kAlways: none); rule text: that condition in words.
// reads: the resolve inputs (common/resolve_inputs.h) the setting makes the resolve sample,
// a C++ lambda of the effective settings returning a ResolveInputSet (kReadsNothing: none;
// readsIf(condition, {inputs}) in renderer/passes/resolve_inputs.h); the resolve binds, and the
// plan allocates, the union over the settings its path runs. A float is a uniform and
// cannot change what a pipeline reads.
// Uniform slots index TaaUniforms::settings (4 floats a vec4); a new float takes the
// next free slot, and TAA_SETTING_VEC4S grows when they are full.
#define TAA_SETTING_VEC4S 4

// The resolve's own specialization constants, which no case key sets, beside the settings'
// ids so that a new one is picked against all of them (renderer/passes/taa_resolve.cpp
// refuses to compile when two ids collide). The next free id is 28.
// X(id, GLSL type, GLSL constant, GLSL default)
#define TAA_SPEC_RESOLVE 0       // RESOLVE_*: which path (renderer/spec/taa_modes.h)
#define TAA_SPEC_HAS_HISTORY 1   // false on frame 0, cuts and scripted resets
#define TAA_SPEC_UPSAMPLE 19     // the output is larger than the render size
#define TAA_SPEC_DEBUG 20        // DEBUG_OUTPUT_*
#define TAA_SPEC_REJECT_MASK 21  // write TAA_BINDING_REJECT_OUT (adaptive mode only)
#define TAA_RESOLVE_CONSTANTS(X)                         \
  X(TAA_SPEC_RESOLVE, int, kResolve, RESOLVE_FULL)       \
  X(TAA_SPEC_HAS_HISTORY, bool, kHasHistory, true)       \
  X(TAA_SPEC_UPSAMPLE, bool, kUpsample, false)           \
  X(TAA_SPEC_DEBUG, int, kDebug, DEBUG_OUTPUT_NONE)      \
  X(TAA_SPEC_REJECT_MASK, bool, kRejectMask, false)

// clang-format off
#define TAA_SETTINGS(E, B, F)                                                                      \
  F(alpha, 0.1f, 0.0f, 1.0f, 0, TAA_PARAM_ALPHA, kBlending, kAlways, "",                           \
    "weight of the current sample (higher = less history)", "shaders/taa/blend_weight.glsl")       \
  E(tonemap_weighting, ToneWeight, TAA_TONE_WEIGHT_VALUES, TONE_WEIGHT_NONE, 2, kToneWeight,       \
    kBlendingNotAccumulate, kReadsNothing, kAlways, "",                                            \
    "blend in a luminance-weighted space against flicker: Karis (1/(1+luma)), inverse luminance "  \
    "tonemap, or log",                                                                             \
    "shaders/taa/color_space.glsl")                                                                \
  E(use_velocity, UseVelocity, TAA_USE_VELOCITY_VALUES, USE_VELOCITY_ALL, 3, kUseVelocity,         \
    kReprojecting,                                                                                 \
    [](const TaaSpec& t) {                                                                         \
      if (t.velocity_in_alpha) return ResolveInputSet{};                                           \
      return ResolveInputSet{ResolveInput::Depth} |                                                \
             readsIf(t.use_velocity != UseVelocity::Off, {ResolveInput::Velocity}) |               \
             readsIf(t.use_velocity == UseVelocity::Movers, {ResolveInput::Ids});                  \
    },                                                                                             \
    kAlways, "",                                                                                   \
    "where the motion-vector buffer drives reprojection: off (depth + inverse view-projection "    \
    "everywhere), "                                                                                \
    "movers (velocity on movers, depth elsewhere) or all",                                         \
    "shaders/taa/reprojection.glsl")                                                               \
  E(velocity_sampling, VelocitySampling, TAA_VELOCITY_SAMPLING_VALUES,                             \
    VELOCITY_SAMPLING_CLOSEST_3X3, 4, kVelocitySampling, kReprojecting, kReadsNothing, kAlways,    \
    "",                                                                                            \
    "which velocity a pixel uses: its own, the longest in 3x3, or the depth-closest in 3x3",       \
    "shaders/taa/reprojection.glsl")                                                               \
  E(history_filter, HistoryFilter, TAA_HISTORY_FILTER_VALUES, HISTORY_FILTER_CATMULL_ROM_5, 5,     \
    kHistoryFilter, kFullOnly, kReadsNothing, kAlways, "",                                         \
    "history resampling: bilinear, B-spline (4 taps), Catmull-Rom 9-tap, 5-tap approximation or "  \
    "16-tap",                                                                                      \
    "shaders/taa/history_filter.glsl")                                                             \
  B(reject_offscreen, true, 6, kRejectOffscreen, kReprojecting, kReadsNothing, kAlways, "",        \
    "reject history whose position falls outside the previous frame",                              \
    "shaders/taa/validation.glsl")                                                                 \
  B(depth_culling, false, 7, kDepthCulling, kFullOnly,                                             \
    [](const TaaSpec& t) { return readsIf(t.depth_culling, {ResolveInput::PrevDepth}); },          \
    kAlways, "",                                                                                   \
    "reject history whose previous depth differs from the expected one",                           \
    "shaders/taa/validation.glsl")                                                                 \
  F(depth_threshold, 0.05f, 0.0f, 10.0f, 5, TAA_PARAM_DEPTH_THRESHOLD, kFullOnly,                  \
    [](const TaaSpec& t) { return t.depth_culling; }, "taa.depth_culling is true",                 \
    "relative linear-depth difference beyond which depth culling rejects",                         \
    "shaders/taa/validation.glsl")                                                                 \
  B(consistency, false, 8, kConsistency, kFullOnly,                                                \
    [](const TaaSpec& t) {                                                                         \
      return readsIf(t.consistency,                                                                \
                     {ResolveInput::Depth, ResolveInput::Ids, ResolveInput::Normal,                \
                      ResolveInput::PrevDepth, ResolveInput::PrevNormal, ResolveInput::PrevIds});  \
    },                                                                                             \
    kAlways, "",                                                                                   \
    "geometric consistency per bilinear tap (depth, normal, mesh id); 2x2, then 3x3, else the "    \
    "current sample",                                                                              \
    "shaders/taa/consistency.glsl")                                                                \
  F(consistency_depth, 0.05f, 0.0f, 10.0f, 7, TAA_PARAM_CONSISTENCY_DEPTH, kReprojecting,          \
    [](const TaaSpec& t) { return t.consistency; }, "taa.consistency is true",                     \
    "relative linear-depth tolerance of a consistent tap", "shaders/taa/consistency.glsl")         \
  F(consistency_normal, 0.9f, -1.0f, 1.0f, 8, TAA_PARAM_CONSISTENCY_NORMAL, kReprojecting,         \
    [](const TaaSpec& t) { return t.consistency; }, "taa.consistency is true",                     \
    "minimum dot product of current and previous normals of a consistent tap",                     \
    "shaders/taa/consistency.glsl")                                                                \
  B(anti_ghosting, false, 9, kAntiGhosting, kFullOnly,                                             \
    [](const TaaSpec& t) {                                                                         \
      return readsIf(t.anti_ghosting, {ResolveInput::Velocity, ResolveInput::Ids,                  \
                                       ResolveInput::PrevIds, ResolveInput::PrevVelocity});        \
    },                                                                                             \
    kAlways, "",                                                                                   \
    "dynamic anti-ghosting: reject history where a mover moved at this pixel last frame and "      \
    "nothing moves in the 5-tap neighbourhood now",                                                \
    "shaders/taa/validation.glsl")                                                                 \
  F(rejection_alpha, 1.0f, 0.0f, 1.0f, 1, TAA_PARAM_REJECTION_ALPHA, kReprojecting, kAlways, "",   \
    "alpha where history is rejected (1 = the current sample)", "shaders/taa/blend_weight.glsl")   \
  E(rectify, Rectify, TAA_RECTIFY_VALUES, RECTIFY_CLIP, 10, kRectify, kFullOnly, kReadsNothing,    \
    kAlways, "",                                                                                   \
    "history rectification against the 3x3 neighbourhood: none, clamp to the box, or clip toward " \
    "its centre",                                                                                  \
    "shaders/taa/rectify.glsl")                                                                    \
  B(variance_clip, false, 11, kVarianceClip, kFullOnly, kReadsNothing,                             \
    [](const TaaSpec& t) { return t.rectify != Rectify::None; }, "taa.rectify is clamp or clip",   \
    "use mean +- gamma * sigma of the neighbourhood as the box",                                   \
    "shaders/taa/neighborhood.glsl")                                                               \
  F(variance_gamma, 1.0f, 0.0f, 10.0f, 4, TAA_PARAM_VARIANCE_GAMMA, kFullOnly,                     \
    [](const TaaSpec& t) { return t.variance_clip && !t.motion_adaptive_gamma; },                  \
    "taa.variance_clip is true and taa.motion_adaptive_gamma is false",                            \
    "gamma of variance clipping", "shaders/taa/neighborhood.glsl")                                 \
  B(motion_adaptive_gamma, false, 23, kMotionAdaptiveGamma, kFullOnly, kReadsNothing,              \
    [](const TaaSpec& t) { return t.variance_clip; }, "taa.variance_clip is true",                 \
    "Intel TAA sample: the variance-clipping gamma goes from variance_gamma_static (still pixels " \
    "keep highlights a tight box would cut) to variance_gamma_moving (moving pixels lose their "   \
    "trails), lerped by the square of 1 - speed / variance_gamma_velocity_px; replaces "           \
    "variance_gamma",                                                                              \
    "shaders/taa/neighborhood.glsl")                                                               \
  F(variance_gamma_moving, 0.75f, 0.0f, 10.0f, 9, TAA_PARAM_VARIANCE_GAMMA_MOVING, kFullOnly,      \
    [](const TaaSpec& t) { return t.motion_adaptive_gamma; }, "taa.motion_adaptive_gamma is true", \
    "variance gamma of pixels moving at variance_gamma_velocity_px or faster",                     \
    "shaders/taa/neighborhood.glsl")                                                               \
  F(variance_gamma_static, 2.0f, 0.0f, 10.0f, 10, TAA_PARAM_VARIANCE_GAMMA_STATIC, kFullOnly,      \
    [](const TaaSpec& t) { return t.motion_adaptive_gamma; }, "taa.motion_adaptive_gamma is true", \
    "variance gamma of still pixels", "shaders/taa/neighborhood.glsl")                             \
  F(variance_gamma_velocity_px, 128.0f, 1e-3f, 1e6f, 11, TAA_PARAM_VARIANCE_GAMMA_VELOCITY_PX,     \
    kFullOnly, [](const TaaSpec& t) { return t.motion_adaptive_gamma; },                           \
    "taa.motion_adaptive_gamma is true",                                                           \
    "speed (output pixels per frame) at which the gamma reaches variance_gamma_moving (Intel: "    \
    "128 at 1080p)",                                                                               \
    "shaders/taa/neighborhood.glsl")                                                               \
  B(shaped_neighborhood, false, 12, kShaped, kFullOnly, kReadsNothing,                             \
    [](const TaaSpec& t) { return t.rectify != Rectify::None; }, "taa.rectify is clamp or clip",   \
    "average the 3x3 box with the 5-tap cross box", "shaders/taa/neighborhood.glsl")               \
  E(color_space, ColorSpace, TAA_COLOR_SPACE_VALUES, COLOR_SPACE_YCOCG, 13, kColorSpace,           \
    kFullOnly, kReadsNothing, [](const TaaSpec& t) { return t.rectify != Rectify::None; },         \
    "taa.rectify is clamp or clip", "space of the box and clipping: rgb or ycocg",                 \
    "shaders/taa/color_space.glsl")                                                                \
  B(shrink_chroma, false, 14, kShrinkChroma, kFullOnly, kReadsNothing,                             \
    [](const TaaSpec& t) {                                                                         \
      return t.rectify != Rectify::None && t.color_space == ColorSpace::YCoCg;                     \
    },                                                                                             \
    "taa.rectify is clamp or clip and taa.color_space is ycocg",                                   \
    "YCoCg only: chroma extent of the box shrinks to a quarter of the luma extent around the "     \
    "current pixel's "                                                                             \
    "chroma",                                                                                      \
    "shaders/taa/neighborhood.glsl")                                                               \
  B(luma_weight, false, 15, kLumaWeight, kFullOnly, kReadsNothing, kAlways, "",                    \
    "Lottes luma weighting: alpha from the luma difference of current and history, within "        \
    "[alpha_min, "                                                                                 \
    "alpha_max]",                                                                                  \
    "shaders/taa/blend_weight.glsl")                                                               \
  F(alpha_min, 0.04f, 0.0f, 1.0f, 2, TAA_PARAM_ALPHA_MIN, kFullOnly,                               \
    [](const TaaSpec& t) { return t.luma_weight; }, "taa.luma_weight is true",                     \
    "smallest alpha of luma weighting", "shaders/taa/blend_weight.glsl")                           \
  F(alpha_max, 0.2f, 0.0f, 1.0f, 3, TAA_PARAM_ALPHA_MAX, kFullOnly,                                \
    [](const TaaSpec& t) { return t.luma_weight; }, "taa.luma_weight is true",                     \
    "largest alpha of luma weighting", "shaders/taa/blend_weight.glsl")                            \
  B(velocity_alpha, false, 16, kVelocityAlpha, kFullOnly, kReadsNothing, kAlways, "",              \
    "fast pixels trust the current frame: alpha rises to 1 at velocity_alpha_px of motion",        \
    "shaders/taa/blend_weight.glsl")                                                               \
  F(velocity_alpha_px, 32.0f, 1e-3f, 1e6f, 6, TAA_PARAM_VELOCITY_ALPHA_PX, kFullOnly,              \
    [](const TaaSpec& t) { return t.velocity_alpha; }, "taa.velocity_alpha is true",               \
    "speed (output pixels per frame) at which velocity_alpha reaches alpha 1",                     \
    "shaders/taa/blend_weight.glsl")                                                               \
  B(velocity_attenuation, false, 24, kVelocityAttenuation, kFullOnly, kReadsNothing, kAlways, "",  \
    "seed 001: the history's weight is divided by 1 + the distance (output pixels) to the "        \
    "pixel's position last frame, so 1 pixel away halves it",                                      \
    "shaders/taa/blend_weight.glsl")                                                               \
  B(reduce_blend_near_clamp, false, 17, kReduceBlend, kFullOnly, kReadsNothing,                    \
    [](const TaaSpec& t) { return t.rectify != Rectify::None; }, "taa.rectify is clamp or clip",   \
    "Karis anti-flicker: lower alpha (to half on the edge) as the history's luma nears the "       \
    "edge of the box",                                                                             \
    "shaders/taa/blend_weight.glsl")                                                               \
  B(velocity_in_alpha, false, 18, kVelocityInAlpha, kFullOnly, kReadsNothing, kAlways, "",         \
    "motion blur packs the per-pixel speed into colour alpha and the resolve reads colour only, "  \
    "no depth and no reprojection (seed 001; mode full, velocity_alpha or velocity_attenuation, "  \
    "use_velocity off); without post.motion_blur it falls back to the velocity buffer",            \
    "shaders/motion_blur.comp")                                                                    \
  B(unjitter_current, false, 25, kUnjitterCurrent, kFullOnly, kReadsNothing, kAlways, "",          \
    "seed 000 (a debugging aid): the blend's current sample is the colour at the pixel centre, "   \
    "bilinear between the jittered samples, instead of the pixel's jittered sample",               \
    "shaders/taa/unjitter.glsl")                                                                   \
  B(unjitter_neighborhood, false, 26, kUnjitterNeighborhood, kFullOnly, kReadsNothing,             \
    [](const TaaSpec& t) { return t.rectify != Rectify::None; }, "taa.rectify is clamp or clip",   \
    "seed 000 (a debugging aid): the 8 neighbours of the 3x3 box are the colours at their pixel "  \
    "centres, bilinear between the jittered samples",                                              \
    "shaders/taa/unjitter.glsl")                                                                   \
  B(noise, false, 27, kNoise, kBlending, kReadsNothing, kAlways, "",                               \
    "seed 000 (experimental): add noise to the output, uniform in +-noise_amount, the same in "    \
    "every channel, a hash of the pixel and the frame index",                                      \
    "shaders/taa/output_noise.glsl")                                                               \
  F(noise_amount, 0.00196078431f, 0.0f, 1.0f, 12, TAA_PARAM_NOISE_AMOUNT, kBlending,               \
    [](const TaaSpec& t) { return t.noise; }, "taa.noise is true",                                 \
    "largest noise added per channel (the seed's code: 1/510, half an 8-bit step)",                \
    "shaders/taa/output_noise.glsl")                                                               \
  E(history_format, HistoryFormat, TAA_HISTORY_FORMAT_VALUES, HISTORY_FORMAT_RGBA16F, 22,          \
    kHistoryFormat, kBlending, kReadsNothing, kAlways, "", "precision of the history buffer",      \
    "renderer/passes/taa_resolve.cpp")
// clang-format on

// The rejection tests that judge history on screen (their reasons run from
// TAA_REJECT_FIRST_ON_SCREEN, common/shared.h), by key. Each compares this pixel with last
// frame's surface at the reprojected position, so validation refuses it where the resolve does
// not reproject (taa.velocity_in_alpha), and adaptive tracing (adaptive.trace_disoccluded)
// traces what they reject, so it needs one of them. A new rejection test is listed here.
#define TAA_ON_SCREEN_REJECTIONS(X) X(depth_culling) X(consistency) X(anti_ghosting)

#endif
