// The public headers' helpers that only some resolves call, each held to what its comment
// promises, in GLSL (taa_user.h) and HLSL (taa_user.hlsli):
// - taa_prev_velocity_uv gives last frame's velocity in UV units of last frame's render area.
//   Under a steady strafe over the checkerboard's ground a point of the screen moves as fast in
//   UV on every frame, so last frame's velocity at this pixel's UV equals this frame's; the
//   render size changes between the frames read (dynamic resolution), so a helper scaling by
//   this frame's size is off by the ratio of the two sizes.
// - taa_jitter_uv and taa_prev_jitter_uv are the pixel jitters in UV units of this frame's and
//   last frame's render area, and the previous jitter is last frame's jitter: under dynamic
//   resolution a helper dividing by the other frame's size is off by the ratio of the sizes.
// - taa_render_pixel maps an output pixel to the render pixel under it in this frame's render
//   area: its centre lies within half a render pixel of the output pixel's, in UV.
// - The current colour sampled bilinearly (GLSL: taa_color_linear; HLSL: taa_color through
//   taa_linear_clamp) at the corner of four pixels is their mean; a point sampler returns one
//   of them, which differs on every checker edge.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "case/case_loader.h"
#include "support/gpu.h"

namespace taa::user_header_helpers_test {

namespace fs = std::filesystem;

const char* kPrevVelocityGlsl = R"(#version 450
#define TAA_USE_DEPTH
#define TAA_USE_VELOCITY
#define TAA_USE_PREV_VELOCITY
#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 r = taa_render_pixel(p);
  vec2 uv = (vec2(r) + 0.5) * taa_frame.renderSize.zw;
  ivec2 q = ivec2(uv * taa_frame.prevRenderSize.xy);
  vec2 now = taa_velocity_uv(r, TAA_CURRENT_MINUS_PREVIOUS);
  vec2 before = taa_prev_velocity_uv(q, TAA_CURRENT_MINUS_PREVIOUS);
  bool ground = texelFetch(taa_depth, r, 0).x > 0.0 && taa_has_history();
  imageStore(taa_output, p, vec4(now.x, before.x, ground ? 1.0 : 0.0, 0.0));
}
)";

const char* kPrevVelocityHlsl = R"(#define TAA_USE_DEPTH
#define TAA_USE_VELOCITY
#define TAA_USE_PREV_VELOCITY
#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.hlsli"
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  int2 r = taa_render_pixel(p);
  float2 uv = (float2(r) + 0.5) * taa_frame.renderSize.zw;
  int2 q = int2(uv * taa_frame.prevRenderSize.xy);
  float2 now = taa_velocity_uv(r, TAA_CURRENT_MINUS_PREVIOUS);
  float2 before = taa_prev_velocity_uv(q, TAA_CURRENT_MINUS_PREVIOUS);
  bool ground = taa_depth.Load(int3(r, 0)) > 0.0 && taa_has_history();
  taa_output[p] = float4(now.x, before.x, ground ? 1.0 : 0.0, 0.0);
}
)";

// r: how far each jitter's UV form, times its frame's render size, is from its pixel form;
// g: last frame's jitter (pixels, x); b: this frame's.
const char* kJitterGlsl = R"(#version 450
#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  vec2 off = abs(taa_jitter_uv() * taa_frame.renderSize.xy - taa_jitter_pixels()) +
             abs(taa_prev_jitter_uv() * taa_frame.prevRenderSize.xy - taa_prev_jitter_pixels());
  imageStore(taa_output, p, vec4(off.x + off.y, taa_prev_jitter_pixels().x, taa_jitter_pixels().x, 1.0));
}
)";

const char* kJitterHlsl = R"(#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.hlsli"
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  float2 off = abs(taa_jitter_uv() * taa_frame.renderSize.xy - taa_jitter_pixels()) +
               abs(taa_prev_jitter_uv() * taa_frame.prevRenderSize.xy - taa_prev_jitter_pixels());
  taa_output[p] = float4(off.x + off.y, taa_prev_jitter_pixels().x, taa_jitter_pixels().x, 1.0);
}
)";

// The render pixel under each output pixel, and this frame's render size.
const char* kRenderPixelGlsl = R"(#version 450
#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 r = taa_render_pixel(p);
  imageStore(taa_output, p, vec4(r, taa_frame.renderSize.xy));
}
)";

const char* kRenderPixelHlsl = R"(#define TAA_SUPPORTS_DYNAMIC_RESOLUTION
#define TAA_SUPPORTS_UPSAMPLING
#include "taa_user.hlsli"
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  int2 r = taa_render_pixel(p);
  taa_output[p] = float4(r, taa_frame.renderSize.xy);
}
)";

// x: |bilinear - mean of the four|, y: |one of the four - their mean| (what a point sampler
// could return), at the corner below-right of each pixel.
const char* kBilinearGlsl = R"(#version 450
#define TAA_USE_COLOR_LINEAR
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  ivec2 last = ivec2(taa_frame.renderSize.xy) - 2;
  ivec2 c = min(p, last);
  vec3 mean = 0.25 * (taa_color_at(c) + taa_color_at(c + ivec2(1, 0)) +
                      taa_color_at(c + ivec2(0, 1)) + taa_color_at(c + ivec2(1, 1)));
  vec2 uv = taa_input_uv(vec2(c + 1) * taa_frame.renderSize.zw);
  vec3 sampled = textureLod(taa_color_linear, uv, 0.0).rgb;
  imageStore(taa_output, p, vec4(length(sampled - mean), length(taa_color_at(c) - mean), 0.0, 0.0));
}
)";

const char* kBilinearHlsl = R"(#include "taa_user.hlsli"
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  int2 c = min(p, int2(taa_frame.renderSize.xy) - 2);
  float3 mean = 0.25 * (taa_color_at(c) + taa_color_at(c + int2(1, 0)) +
                        taa_color_at(c + int2(0, 1)) + taa_color_at(c + int2(1, 1)));
  float2 uv = taa_input_uv(float2(c + 1) * taa_frame.renderSize.zw);
  float3 sampled = taa_color.SampleLevel(taa_linear_clamp, uv, 0).rgb;
  taa_output[p] = float4(length(sampled - mean), length(taa_color_at(c) - mean), 0.0, 0.0);
}
)";

// Renders `text` as the case's resolve; the output images of `frames`.
std::vector<Image> renderProbe(const std::string& shader, const char* text,
                               const std::string& render, const std::vector<int>& frames) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "user_header_helpers";
  fs::create_directories(dir);
  std::ofstream(dir / shader) << text;
  const fs::path file = dir / (fs::path(shader).stem().string() + ".json");
  std::ofstream(file) << R"({"scene": {"builtin": "checkerboard"}, "render": )" + render + R"(,
    "camera": {"strafe": {"speed": 1.5}}, "script": {"frames": 6, "fps": 30},
    "taa": {"shader": ")" + shader + R"("}})";
  setenv("TAA_SHADER_CACHE", (dir / "cache").c_str(), 1);
  std::vector<Image> out;
  for (const auto& rec : test::renderCase(cases::loadCase(file).spec, frames))
    if (rec.hasImages) out.push_back(rec.color);
  return out;
}

// The render size changes before frames 2 (1.0 -> 0.6) and 4 (0.6 -> 0.8): there, last frame's
// size and this frame's differ, and a helper that takes one for the other is wrong.
constexpr const char* kResizingRender = R"({"width": 96, "height": 64, "scale_schedule": [
    {"frame": 0, "scale": 1.0}, {"frame": 2, "scale": 0.6}, {"frame": 3, "scale": 0.6},
    {"frame": 4, "scale": 0.8}]})";

// Frames 2 and 4 each follow a frame of another render size.
void expectPrevVelocityInLastFramesUv(const std::string& shader, const char* text) {
  const auto images = renderProbe(shader, text, kResizingRender, {2, 4});
  ASSERT_EQ(images.size(), 2u) << shader;
  for (const Image& img : images) {
    double speed = 0.0, error = 0.0;
    size_t n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x)
        if (img.at(x, y, 2) > 0.5f) {
          ++n;
          speed += std::fabs(img.at(x, y, 0));
          error += std::fabs(img.at(x, y, 0) - img.at(x, y, 1));
        }
    ASSERT_GT(n, 1000u) << shader << ": too little ground";
    ASSERT_GT(speed / double(n), 1e-3) << shader << ": the ground does not move";
    // Pixel rounding and the ground's edge: under 4% here; a scale by this frame's size: 60%, 25%.
    EXPECT_LT(error, 0.1 * speed) << shader;
  }
}

// The same render sizes as above; frames 1 to 4, so that each of 2 to 4 has the one before.
void expectJitterHelpers(const std::string& shader, const char* text) {
  const auto images = renderProbe(shader, text, kResizingRender, {1, 2, 3, 4});
  ASSERT_EQ(images.size(), 4u) << shader;
  float moved = 0.0f;
  for (size_t i = 0; i < images.size(); ++i) {
    const Image& img = images[i];
    EXPECT_LT(img.at(3, 3, 0), 2e-3f) << shader << " frame " << i + 1;  // half-float output
    if (i > 0) {
      EXPECT_EQ(img.at(3, 3, 1), images[i - 1].at(3, 3, 2)) << shader << " frame " << i + 1;
    }
    moved += std::fabs(img.at(3, 3, 2));
  }
  ASSERT_GT(moved, 0.1f) << shader << ": no jitter to measure";
}

// Frames 2 and 4 follow a frame of another render size, where last frame's size is the wrong one.
void expectRenderPixelUnderEachOutputPixel(const std::string& shader, const char* text) {
  const auto images = renderProbe(shader, text, kResizingRender, {2, 4});
  ASSERT_EQ(images.size(), 2u) << shader;
  for (const Image& img : images) {
    ASSERT_EQ(img.channels, 4) << shader;
    const float rw = img.at(0, 0, 2), rh = img.at(0, 0, 3);
    ASSERT_LT(rw, 90.0f) << shader << ": the frame is not scaled";
    int far = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        const float u = (float(x) + 0.5f) / float(img.width), v = (float(y) + 0.5f) / float(img.height);
        far += std::fabs((img.at(x, y, 0) + 0.5f) / rw - u) > 0.5f / rw ||
               std::fabs((img.at(x, y, 1) + 0.5f) / rh - v) > 0.5f / rh;
      }
    EXPECT_EQ(far, 0) << shader;
  }
}

void expectBilinearColour(const std::string& shader, const char* text) {
  const auto images = renderProbe(shader, text, R"({"width": 96, "height": 64})", {3});
  ASSERT_EQ(images.size(), 1u) << shader;
  double worst = 0.0, pointError = 0.0;
  for (int y = 0; y < images[0].height; ++y)
    for (int x = 0; x < images[0].width; ++x) {
      worst = std::max(worst, double(images[0].at(x, y, 0)));
      pointError += double(images[0].at(x, y, 1));
    }
  ASSERT_GT(pointError, 1.0) << shader << ": no edge to tell the samplers apart";
  EXPECT_LT(worst, 2e-3) << shader;  // half-float colour and output only
}

TEST(UserHeaderHelpers, GlslPrevVelocityIsInLastFramesRenderUv) {
  expectPrevVelocityInLastFramesUv("prev_velocity_probe.comp", kPrevVelocityGlsl);
}

TEST(UserHeaderHelpers, HlslPrevVelocityIsInLastFramesRenderUv) {
  expectPrevVelocityInLastFramesUv("prev_velocity_probe.hlsl", kPrevVelocityHlsl);
}

TEST(UserHeaderHelpers, GlslJitterHelpersUseTheirOwnFramesRenderSize) {
  expectJitterHelpers("jitter_probe.comp", kJitterGlsl);
}

TEST(UserHeaderHelpers, HlslJitterHelpersUseTheirOwnFramesRenderSize) {
  expectJitterHelpers("jitter_probe.hlsl", kJitterHlsl);
}

TEST(UserHeaderHelpers, GlslRenderPixelIsUnderTheOutputPixelInThisFramesRenderArea) {
  expectRenderPixelUnderEachOutputPixel("render_pixel_probe.comp", kRenderPixelGlsl);
}

TEST(UserHeaderHelpers, HlslRenderPixelIsUnderTheOutputPixelInThisFramesRenderArea) {
  expectRenderPixelUnderEachOutputPixel("render_pixel_probe.hlsl", kRenderPixelHlsl);
}

TEST(UserHeaderHelpers, GlslColourLinearSamplesBilinearly) {
  expectBilinearColour("bilinear_probe.comp", kBilinearGlsl);
}

TEST(UserHeaderHelpers, HlslColourThroughTheLinearSamplerSamplesBilinearly) {
  expectBilinearColour("bilinear_probe.hlsl", kBilinearHlsl);
}

}  // namespace taa::user_header_helpers_test
