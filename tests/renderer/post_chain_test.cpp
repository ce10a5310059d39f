// The post chain inside the renderer: each pass, when enabled, changes the frame,
// appears in the run log and in the GPU timings, and the whole chain is
// deterministic; the case validator refuses settings the passes would ignore.
#include <gtest/gtest.h>

#include <cmath>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <regex>

#include "api/renderer.h"
#include "passes/taa_resolve.h"
#include "scene/build_scene.h"
#include "support/case_problems.h"
#include "support/gpu.h"
#include "support/process.h"

namespace taa {
namespace {

// A strafing camera and a fast mover: motion for the blur, edges for the rest.
const char* kPostChainBase = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 160, "height": 90 %s},
  "camera": {"strafe": {"speed": 3.0, "distance": 1.0}},
  "movers": [{"shape": "sphere", "start": [-1.5, 0.5, 1], "end": [1.5, 0.5, 1], "speed": 4}],
  "script": {"frames": 4},
  "output": {"frames": [3]}
  %s
})";

spec::CaseSpec makeCase(const std::string& extra, const std::string& render = "") {
  char buf[2048];
  std::snprintf(buf, sizeof(buf), kPostChainBase, render.c_str(),
                extra.empty() ? "" : (", " + extra).c_str());
  return test::caseFromJson(buf, "post_chain");
}

struct Rendered {
  std::vector<std::string> log;
  FrameRecord last;
};

Rendered render(const spec::CaseSpec& spec) {
  const auto scene = scene::buildScene(spec);
  Renderer renderer(test::gpu(), spec, scene);
  Rendered out;
  out.log = renderer.log();
  for (int f = 0; f < spec.script.frames; ++f)
    out.last = renderer.renderFrame(f, f == spec.script.frames - 1);
  return out;
}

bool logged(const Rendered& r, const std::string& prefix) {
  return std::any_of(r.log.begin(), r.log.end(),
                     [&](const std::string& l) { return l.rfind(prefix, 0) == 0; });
}

bool timed(const Rendered& r, const std::string& pass) {
  return std::any_of(r.last.gpuMs.begin(), r.last.gpuMs.end(),
                     [&](const auto& t) { return t.first == pass; });
}

double meanAbsDiff(const Image& a, const Image& b) {
  EXPECT_TRUE(a.sameShape(b));
  double sum = 0.0;
  for (size_t i = 0; i < a.data.size(); ++i)
    if (i % 4 != 3) sum += std::fabs(a.data[i] - b.data[i]);
  return sum / double(a.pixelCount() * 3);
}

struct PassCase {
  const char* pass;
  const char* settings;
};

class PostPass : public ::testing::TestWithParam<PassCase> {};

TEST_P(PostPass, ChangesTheFrameAndIsLoggedAndTimed) {
  static const Rendered plain = render(makeCase(""));
  const Rendered with = render(makeCase(GetParam().settings));
  const std::string pass = GetParam().pass;
  EXPECT_TRUE(logged(with, "pass " + pass + ":")) << pass;
  EXPECT_TRUE(logged(with, "buffer " + pass + " ")) << pass;
  EXPECT_FALSE(logged(plain, "pass " + pass));
  EXPECT_TRUE(timed(with, pass));
  EXPECT_FALSE(timed(plain, pass));
  ASSERT_TRUE(with.last.hasImages);
  EXPECT_EQ(with.last.color.width, 160);
  EXPECT_NE(with.last.colorSha256, plain.last.colorSha256);
  EXPECT_GT(meanAbsDiff(with.last.color, plain.last.color), 1e-4) << pass;
}

INSTANTIATE_TEST_SUITE_P(
    Post, PostPass,
    ::testing::Values(PassCase{"motion_blur", R"("post": {"motion_blur": true})"},
                      PassCase{"sharpen",
                               R"("post": {"sharpen": "gradient", "sharpen_amount": 0.8})"},
                      PassCase{"cas", R"("post": {"sharpen": "cas", "sharpen_amount": 0.8})"},
                      PassCase{"fxaa", R"("post": {"fxaa": true})"}),
    [](const auto& p) { return std::string(p.param.pass); });

const char* kEverything =
    R"("taa": {"velocity_in_alpha": true, "velocity_alpha": true, "use_velocity": "off"},
       "post": {"motion_blur": true, "motion_blur_samples": 6, "sharpen": "cas", "fxaa": true})";

TEST(PostChain, AllPassesRunInOrderAndTwiceGiveIdenticalBytes) {
  const auto spec = makeCase(kEverything);
  const Rendered a = render(spec), b = render(spec);
  std::vector<std::string> order;
  for (const auto& t : a.last.gpuMs) order.push_back(t.first);
  EXPECT_EQ(order,
            (std::vector<std::string>{"gbuffer", "motion_blur", "taa_resolve", "cas", "fxaa"}));
  EXPECT_EQ(a.last.colorSha256, b.last.colorSha256);
  for (float v : a.last.color.data) ASSERT_TRUE(std::isfinite(v));
}

// Lavapipe splits dispatches across its threads; no pass may depend on how.
TEST(PostChain, OneAndTwoLavapipeThreadsGiveIdenticalFrames) {
  const std::string dir = std::string(TAA_TEST_OUT) + "/post-threads";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/post_threads.json") << R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 160, "height": 90},
    "camera": {"strafe": {"speed": 3.0, "distance": 1.0}},
    "script": {"frames": 3},
    "output": {"frames": [2]},
    )" << kEverything << "}";
  std::vector<std::string> hashes;
  for (const char* env : {"LP_NUM_THREADS=1", "LP_NUM_THREADS=2"}) {
    const auto r = test::runHarness("render " + dir + "/post_threads.json --out " + dir, env);
    ASSERT_EQ(r.exitCode, 0) << r.output;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.output, m, std::regex("frame 2 sha256 ([0-9a-f]{64})")));
    hashes.push_back(m[1]);
  }
  EXPECT_EQ(hashes[0], hashes[1]);
}

TEST(PostChain, RunsWithoutAResolveAndUnderUpsamplingAtTheRightSizes) {
  // No resolve: the filters work on the (blurred) render-size colour.
  const Rendered off =
      render(makeCase(R"("taa": {"mode": "off"}, "post": {"motion_blur": true, "fxaa": true})"));
  EXPECT_EQ(off.last.color.width, 160);
  EXPECT_TRUE(logged(off, "buffer fxaa 160x90"));
  // Upsampling: blur at the 80x45 render size, sharpening at the 160x90 output.
  const Rendered up = render(
      makeCase(R"("post": {"motion_blur": true, "sharpen": "gradient"})", R"(, "upsample": 2)"));
  EXPECT_TRUE(logged(up, "buffer motion_blur 80x45"));
  EXPECT_TRUE(logged(up, "buffer sharpen 160x90"));
  EXPECT_EQ(up.last.color.width, 160);
  EXPECT_EQ(up.last.color.height, 90);
}

// The smallest frames a case may ask for, one pixel wide or high, go through every post pass
// (each filter checks that its region fits its image, at least 1x1).
TEST(PostChain, OnePixelWideAndHighFramesPassEveryFilter) {
  for (const char* size : {R"("width": 1, "height": 1)", R"("width": 1, "height": 9)",
                           R"("width": 9, "height": 1)"}) {
    SCOPED_TRACE(size);
    const Rendered r = render(test::caseFromJson(
        std::string(R"({"scene": {"builtin": "checkerboard"}, "render": {)") + size +
            R"(}, "camera": {"strafe": {"speed": 3.0}}, "script": {"frames": 2},
            "post": {"motion_blur": true, "fxaa": true, "sharpen": "cas"}})",
        "post_tiny"));
    EXPECT_TRUE(logged(r, "buffer fxaa"));
    EXPECT_TRUE(logged(r, "buffer cas"));
    EXPECT_TRUE(logged(r, "buffer motion_blur"));
    ASSERT_FALSE(r.last.color.data.empty());
    for (const float v : r.last.color.data) EXPECT_TRUE(std::isfinite(v));
  }
}

TEST(PostChain, SpeedInAlphaDrivesTheColourOnlyBlend) {
  // Under the strafe every pixel moves. The colour-only resolve (seed 001) blends last
  // frame's colour at the same pixel, weighted by the speed the blur packed into alpha: at
  // 4 px to alpha 1 the frame comes toward this frame's colour (the resolve off, which also
  // drops the jitter, so not all the way); when the speed barely counts (1e6 px) the
  // unreprojected history stays in it. Measured: 0.115 against 0.167.
  const std::string blur = R"("post": {"motion_blur": true, "motion_blur_scale": 0.0})";
  auto packed = [&](const char* px) {
    return render(makeCase(std::string(R"("taa": {"velocity_in_alpha": true, "velocity_alpha": true,
                                                  "use_velocity": "off", "velocity_alpha_px": )") +
                           px + "}, " + blur));
  };
  const auto fast = packed("4"), slow = packed("1e6");
  const auto current = render(makeCase(R"("taa": {"mode": "off"}, )" + blur));
  const double close = meanAbsDiff(fast.last.color, current.last.color);
  const double far = meanAbsDiff(slow.last.color, current.last.color);
  std::printf("colour-only resolve vs this frame: speed counts %.5f, barely %.5f\n", close, far);
  EXPECT_LT(close, 0.8 * far);
}

// Seed 001: with the speed in alpha the resolve reads the two colours only, no depth and no
// velocity, and the log gives the bytes it reads a pixel (which record() checks against the
// formats of the images it binds).
TEST(PostChain, SpeedInAlphaResolveReadsColourOnly) {
  const auto packed = makeCase(kEverything);
  EXPECT_EQ(taaResolveNeeds(packed), GBufferNeeds{});
  const auto own = makeCase(R"("taa": {"velocity_alpha": true, "use_velocity": "off"},
                                "post": {"motion_blur": true})");
  EXPECT_EQ(taaResolveNeeds(own), GBufferNeeds{.depth = true});
  const auto buffer = makeCase(R"("taa": {"velocity_alpha": true}, "post": {"motion_blur": true})");
  EXPECT_EQ(taaResolveNeeds(buffer), (GBufferNeeds{.velocity = true, .depth = true}));
  EXPECT_EQ(taaResolveReadBytes(packed), 16u);  // colour 8 + history 8
  EXPECT_EQ(taaResolveReadBytes(own), 20u);     // + depth 4
  EXPECT_EQ(taaResolveReadBytes(buffer), 24u);  // + depth 4 + velocity 4
  const Rendered r = render(packed);
  EXPECT_TRUE(logged(r, "taa_resolve reads per pixel: colour 8 + history 8 = 16 bytes"));
  EXPECT_TRUE(logged(render(buffer),
                     "taa_resolve reads per pixel: colour 8 + history 8 + depth 4 + velocity 4 = "
                     "24 bytes"));
}

// Without motion blur nothing writes the speed into alpha: the resolve falls back to the
// velocity buffer, which is the case without velocity_in_alpha, byte for byte, and says so.
TEST(PostChain, SpeedInAlphaWithoutMotionBlurFallsBackToTheVelocityBuffer) {
  const std::string alpha = R"("velocity_alpha": true, "velocity_alpha_px": 4})";
  const auto fallback = makeCase(R"("taa": {"velocity_in_alpha": true, )" + alpha);
  const auto plain = makeCase(R"("taa": {)" + alpha);
  EXPECT_TRUE(taaResolveNeeds(fallback).velocity);
  EXPECT_EQ(taaSpecConstants(fallback, true).describe(), taaSpecConstants(plain, true).describe());
  const Rendered a = render(fallback), b = render(plain);
  EXPECT_EQ(a.last.colorSha256, b.last.colorSha256);
  EXPECT_TRUE(logged(a, "taa_resolve: taa.velocity_in_alpha falls back to the velocity buffer"));
  EXPECT_FALSE(logged(b, "taa_resolve: taa.velocity_in_alpha falls back"));
}

std::vector<std::string> chainProblems(const std::string& extra) {
  return test::caseRefusal([&] { makeCase(extra); });
}

bool mentions(const std::vector<std::string>& problems, const std::string& a,
              const std::string& b) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& p) {
    return p.find(a) != std::string::npos && p.find(b) != std::string::npos;
  });
}

TEST(PostValidation, RefusesSettingsThePassesWouldIgnore) {
  auto p = chainProblems(R"("post": {"sharpen_amount": 0.3})");
  EXPECT_TRUE(mentions(p, "post.sharpen_amount", "post.sharpen to gradient or cas")) << p.size();
  p = chainProblems(R"("post": {"motion_blur_samples": 4, "motion_blur_scale": 0.5})");
  EXPECT_TRUE(mentions(p, "post.motion_blur_samples", "post.motion_blur: true"));
  EXPECT_TRUE(mentions(p, "post.motion_blur_scale", "post.motion_blur: true"));
  p = chainProblems(R"("taa": {"velocity_in_alpha": true}, "post": {"motion_blur": true})");
  EXPECT_TRUE(mentions(p, "taa.velocity_in_alpha", "taa.velocity_alpha: true"));
  EXPECT_TRUE(mentions(p, "taa.velocity_in_alpha", "taa.use_velocity: off"));
  // Without motion blur it falls back to the velocity buffer, which use_velocity off never reads.
  p = chainProblems(R"("taa": {"velocity_in_alpha": true, "velocity_alpha": true,
                            "use_velocity": "off"})");
  EXPECT_TRUE(mentions(p, "taa.velocity_in_alpha", "taa.use_velocity: all"));
  EXPECT_TRUE(chainProblems(R"("taa": {"velocity_in_alpha": true, "velocity_alpha": true})").empty());
  // The colour-only resolve has no depth, velocity or ids for these.
  p = chainProblems(
      R"("taa": {"velocity_in_alpha": true, "velocity_alpha": true, "use_velocity": "off",
                            "depth_culling": true, "consistency": true, "anti_ghosting": true,
                            "velocity_sampling": "pixel", "reject_offscreen": true},
                    "debug": {"output": "velocity"}, "post": {"motion_blur": true})");
  for (const char* key : {"taa.depth_culling", "taa.consistency", "taa.anti_ghosting"})
    EXPECT_TRUE(mentions(p, key, "remove taa.velocity_in_alpha")) << key;
  for (const char* key : {"taa.velocity_sampling", "taa.reject_offscreen"})
    EXPECT_TRUE(mentions(p, key, "does not reproject")) << key;
  EXPECT_TRUE(mentions(p, "debug.output", "taa.velocity_in_alpha"));
  p = chainProblems(R"("taa": {"mode": "basic", "velocity_in_alpha": true, "velocity_alpha": true,
                            "use_velocity": "off"}, "post": {"motion_blur": true})");
  EXPECT_TRUE(mentions(p, "taa.velocity_in_alpha", "taa.mode: full"));
  EXPECT_TRUE(chainProblems(kEverything).empty());
  EXPECT_TRUE(chainProblems(R"("post": {"sharpen": "cas", "sharpen_amount": 0.3, "motion_blur": true,
                                     "motion_blur_samples": 4})")
                  .empty());
}

}  // namespace
}  // namespace taa
