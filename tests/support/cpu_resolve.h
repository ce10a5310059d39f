// A plain C++ mirror of the temporal resolve (shaders/taa_resolve.comp and shaders/taa/*.glsl),
// written from the shader's formulas in float, so the GPU result can be checked pixel by pixel
// and the formulas themselves can be tested without a GPU. It covers the full mode without
// upsampling, with velocity reprojection from one constant velocity (use_velocity all, velocity
// sampling pixel); the geometric rejection tests (depth, consistency, anti-ghosting) are not
// mirrored and cpuResolve refuses specs that enable them.
//
// Why a mirror at all, when the GPU tests run the real shader: it checks what they cannot.
// (1) The filters' algebra to 1e-6 (cpu_history_filter_test: merged taps reproduce ramps and
// texel centres exactly); the GPU's bilinear hardware filter quantises its weights, so exactness
// is not observable there. (2) Intermediate values the shader never writes out: the box's lo /
// hi / mean, the rectified history, the alpha of each dynamic-alpha technique (cpu_resolve_test).
// (3) That the shader computes the published formula rather than merely the same image as
// yesterday (ResolveAgreement): a golden says "unchanged", not "right". Techniques without
// such a need are tested through the GPU against their properties (e.g.
// motion_adaptive_gamma_test.cpp), and the mirror refuses settings it does not cover.
#pragma once

#include <array>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image.h"
#include "spec/taa_spec.h"

namespace taa::test::cpu {

inline constexpr float kHalfMax = 65504.0f;

// ---- colour spaces and blends (color_space.glsl) ----
float luma(glm::vec3 rgb);
glm::vec3 rgbToYCoCg(glm::vec3 rgb);
glm::vec3 yCoCgToRgb(glm::vec3 c);
// The resolve's working space: the tone domain of inverse_luma / log (identity for
// none and Karis), then YCoCg or RGB.
glm::vec3 toWorking(glm::vec3 rgb, bool yCoCg, spec::ToneWeight weighting = spec::ToneWeight::None);
glm::vec3 fromWorking(glm::vec3 w, bool yCoCg, spec::ToneWeight weighting = spec::ToneWeight::None);
float workingLuma(glm::vec3 w, bool yCoCg);
// Blends history toward current by alpha (the current sample's weight).
glm::vec3 toneWeightedBlend(glm::vec3 history, glm::vec3 current, float alpha,
                            spec::ToneWeight weighting);
glm::vec3 boundColor(glm::vec3 c);

// ---- history resampling (history_filter.glsl) ----
// `image` is the history; uv in [0, 1] with texel centres at (i + 0.5) / size. Out-of-range
// texels clamp to the edge, as the resolve's sampler does. bilinear is exact (float weights),
// standing in for textureLod wherever the shader uses the hardware filter.
glm::vec3 bilinear(const Image& image, glm::vec2 uv);
glm::vec3 historyBSpline(const Image& image, glm::vec2 uv);
glm::vec3 historyCatmullRom9(const Image& image, glm::vec2 uv);
glm::vec3 historyCatmullRom5(const Image& image, glm::vec2 uv);
glm::vec3 historyCatmullRom16(const Image& image, glm::vec2 uv);
// The filter the case chose, with negative lobes cut at zero as the resolve does.
glm::vec3 sampleHistory(const Image& image, glm::vec2 uv, spec::HistoryFilter filter);

// ---- neighbourhood box and rectification (neighborhood.glsl, rectify.glsl) ----
struct Box {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
  glm::vec3 mean{0.0f};
};

// The 3x3 samples in working space, row-major, centre at 4; invalid (NaN) taps do not
// shape the box.
struct Neighborhood {
  std::array<glm::vec3, 9> taps{};
  std::array<bool, 9> valid{};
};

// Uses the spec's shaped_neighborhood, variance_clip / variance_gamma, color_space and
// shrink_chroma.
Box neighborhoodBox(const Neighborhood& n, glm::vec3 center, const spec::TaaSpec& taa);
glm::vec3 clampToBox(glm::vec3 h, const Box& b);
glm::vec3 clipToBox(glm::vec3 h, const Box& b);
glm::vec3 rectifyHistory(glm::vec3 h, const Box& b, spec::Rectify rectify);

// ---- dynamic alpha (blend_weight.glsl) ----
float lottesAlpha(float lumaCurrent, float lumaHistory, float alphaMin, float alphaMax);
float reduceBlendNearClamp(float alpha, float lumaHistory, float lo, float hi);
float velocityAlpha(float alpha, float speedPx, float fullSpeedPx);

// ---- the whole resolve ----
struct CpuResolveInputs {
  const Image& current;  // render size == output size, RGB(A)
  const Image& history;  // last output, same size, RGB(A)
  glm::vec2 velocityPx;  // every pixel's motion this frame, in render pixels (as RG16F stores it)
};

// The resolve's output (RGBA, alpha 1) before it is stored: float, not rounded to the history
// format. Throws std::invalid_argument for settings outside what the mirror covers.
Image cpuResolve(const CpuResolveInputs& in, const spec::TaaSpec& taa);

}  // namespace taa::test::cpu
