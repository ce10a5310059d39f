// The public headers are held to the renderer: a probe resolve, once in GLSL (taa_user.h)
// and once in HLSL (taa_user.hlsli), un-jitters each pixel as TaaUserFrame.jitter's comment
// says, reconstructs the surface point from the depth and invViewProj, and reprojects it with
// prevViewProj and with taa_velocity_uv. On the checkerboard's ground (normal up, y = 0) the
// point must land on the plane, the two reprojections must agree, and the frame constants
// must carry the fixed timestep. With the jitter's sign flipped the plane is missed by far
// more, so a header stating the wrong sign fails here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "support/gpu.h"
#include "support/text.h"

namespace {

namespace fs = std::filesystem;

const char* kGlslProbe = R"(#version 450
#define TAA_USE_DEPTH
#define TAA_USE_VELOCITY
#define TAA_USE_NORMAL
#include "taa_user.h"
layout(constant_id = 0) const float jitter_sign = 1.0;  // -1: the opposite of the header
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  float depth = texelFetch(taa_depth, p, 0).x;
  vec3 n = texelFetch(taa_normal, p, 0).xyz;
  vec2 uv = (vec2(p) + 0.5 - jitter_sign * taa_jitter_pixels()) * taa_frame.renderSize.zw;
  vec4 w = taa_frame.invViewProj * vec4(uv * 2.0 - 1.0, depth, 1.0);
  vec3 world = w.xyz / w.w;
  vec4 prev = taa_frame.prevViewProj * vec4(world, 1.0);
  vec2 prevUv = prev.xy / prev.w * 0.5 + 0.5;
  vec2 moved = uv - taa_velocity_uv(p, TAA_CURRENT_MINUS_PREVIOUS);
  float px = length((prevUv - moved) * taa_frame.renderSize.xy);
  bool ground = depth > 0.0 && n.y > 0.99 && abs(world.y) < 0.5;
  imageStore(taa_output, p, vec4(world.y, px, taa_frame.time.y - taa_frame.time.x * float(taa_frame.info.x),
                                 ground ? taa_linear_depth(depth) : 0.0));
}
)";

const char* kHlslProbe = R"(#define TAA_USE_DEPTH
#define TAA_USE_VELOCITY
#define TAA_USE_NORMAL
#include "taa_user.hlsli"
[[vk::constant_id(0)]] const float jitter_sign = 1.0;
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  float depth = taa_depth.Load(int3(p, 0));
  float3 n = taa_normal.Load(int3(p, 0)).xyz;
  float2 uv = (float2(p) + 0.5 - jitter_sign * taa_jitter_pixels()) * taa_frame.renderSize.zw;
  float4 w = mul(taa_frame.invViewProj, float4(uv * 2.0 - 1.0, depth, 1.0));
  float3 world = w.xyz / w.w;
  float4 prev = mul(taa_frame.prevViewProj, float4(world, 1.0));
  float2 prevUv = prev.xy / prev.w * 0.5 + 0.5;
  float2 moved = uv - taa_velocity_uv(p, TAA_CURRENT_MINUS_PREVIOUS);
  float px = length((prevUv - moved) * taa_frame.renderSize.xy);
  bool ground = depth > 0.0 && n.y > 0.99 && abs(world.y) < 0.5;
  taa_output[p] = float4(world.y, px, taa_frame.time.y - taa_frame.time.x * float(taa_frame.info.x),
                         ground ? taa_linear_depth(depth) : 0.0);
}
)";

struct ProbeResult {
  double meanPlaneError = 0.0;  // mean |y| of ground pixels, world units
  double worstReprojection = 0.0;  // pixels between prevViewProj's and the velocity's answer
  double worstTime = 0.0;          // |time.y - frame * time.x|
  size_t ground = 0;
};

ProbeResult probe(const std::string& shader, const char* text, float sign) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "user_header";
  fs::create_directories(dir);
  std::ofstream(dir / shader) << text;
  const std::string caseJson = R"({"scene": {"builtin": "checkerboard"},
    "render": {"width": 96, "height": 64},
    "camera": {"strafe": {"speed": 1.5, "distance": 0.5}},
    "script": {"frames": 4, "fps": 30},
    "taa": {"shader": ")" + shader + R"(", "shader_params": [{"name": "jitter_sign", "value": )" +
                               std::to_string(sign) + "}]}}";
  const fs::path file = dir / (fs::path(shader).stem().string() + (sign > 0 ? "" : "_flipped") + ".json");
  std::ofstream(file) << caseJson;
  setenv("TAA_SHADER_CACHE", (dir / "cache").c_str(), 1);
  const auto loaded = taa::cases::loadCase(file);
  const auto records = taa::test::renderCase(loaded.spec, {1, 2, 3});
  ProbeResult r;
  double sum = 0.0;
  for (const auto& rec : records) {
    if (!rec.hasImages) continue;
    const taa::Image& img = rec.color;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) {
        r.worstTime = std::max(r.worstTime, double(std::fabs(img.at(x, y, 2))));
        // Near ground only: far away a depth step is centimetres of world.
        const float distance = img.at(x, y, 3);
        if (distance <= 0.0f || distance > 8.0f) continue;
        ++r.ground;
        sum += std::fabs(img.at(x, y, 0));
        r.worstReprojection = std::max(r.worstReprojection, double(img.at(x, y, 1)));
      }
  }
  r.meanPlaneError = r.ground ? sum / double(r.ground) : 1e9;
  return r;
}

void expectHeaderMatchesRenderer(const std::string& shader, const char* text) {
  const ProbeResult stated = probe(shader, text, 1.0f);
  const ProbeResult flipped = probe(shader, text, -1.0f);
  ASSERT_GT(stated.ground, 1000u) << shader << ": the probe saw too little ground";
  // The stated sign puts the point on the plane (depth quantisation and half-float output
  // only); the opposite sign misses it by a jitter's worth of ground.
  EXPECT_LT(stated.meanPlaneError, 2e-4) << shader;
  EXPECT_GT(flipped.meanPlaneError, 10.0 * stated.meanPlaneError) << shader;
  // Velocity: current minus previous, un-jittered, as taa_velocity_uv says.
  EXPECT_LT(stated.worstReprojection, 0.02) << shader;
  // time.y is frame * time.x (1 / fps) in seconds.
  EXPECT_LT(stated.worstTime, 1e-6) << shader;
}

TEST(UserHeaderTest, GlslHeaderStatesTheRenderersJitterVelocityAndTime) {
  expectHeaderMatchesRenderer("probe.comp", kGlslProbe);
}

TEST(UserHeaderTest, HlslHeaderStatesTheRenderersJitterVelocityAndTime) {
  expectHeaderMatchesRenderer("probe.hlsl", kHlslProbe);
}

// docs/user-taa.md's shared-memory tile example, compiled from the doc itself: reaching the
// barrier before the early return, it renders the minimal clamp's frames bit for bit.
TEST(UserHeaderTest, DocsTilePatternRendersTheMinimalClamp) {
  const std::string doc = taa::test::readFile(fs::path(TAA_SOURCE_DIR) / "docs" / "user-taa.md");
  const size_t section = doc.find("### The shared-memory tile pattern");
  ASSERT_NE(section, std::string::npos);
  const size_t begin = doc.find("```glsl\n", section) + 8;
  const size_t end = doc.find("```", begin);
  ASSERT_LT(begin, end);
  const fs::path dir = fs::path(TAA_TEST_OUT) / "user_docs_tile";
  fs::create_directories(dir);
  std::ofstream(dir / "tile.comp") << doc.substr(begin, end - begin);
  const fs::path examples = fs::path(TAA_SOURCE_DIR) / "examples" / "user_taa" / "cases";
  // The minimal clamp's case on the tile shader, which hard-codes its alpha of 0.1.
  auto json = nlohmann::json::parse(taa::test::readFile(examples / "minimal_clamp.json"));
  json["taa"] = {{"shader", "tile.comp"}};
  json.erase("checks");
  setenv("TAA_SHADER_CACHE", (dir / "cache").c_str(), 1);
  const auto tile = taa::cases::parseCase(json.dump(), dir / "tile.json");
  const auto clamp = taa::cases::loadCase(examples / "minimal_clamp.json");
  std::vector<int> all(24);
  for (int f = 0; f < 24; ++f) all[size_t(f)] = f;
  const auto a = taa::test::renderCase(clamp.spec, all);
  const auto b = taa::test::renderCase(tile.spec, all);
  ASSERT_EQ(a.size(), 24u);
  ASSERT_EQ(b.size(), 24u);
  for (size_t f = 0; f < a.size(); ++f) {
    ASSERT_FALSE(a[f].colorSha256.empty());
    EXPECT_EQ(a[f].colorSha256, b[f].colorSha256) << "frame " << f;
  }
}

}  // namespace
