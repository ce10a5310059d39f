// Section 11 of the contract, the resolve's rows from seed 000: unjittering the current sample
// and the neighbourhood (debugging aids there) and the experimental output noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "script/frame_state.h"
#include "support/case_problems.h"
#include "support/effects.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"
#include "support/noise.h"

namespace taa {
namespace {

// A still view of the open area with Halton jitter. With alpha 1 and no rectification the
// output is the current sample alone.
const char* kStillJittered = R"({"scene": {"builtin": "open_area"},
  "render": {"width": 160, "height": 90}, "script": {"frames": 4},
  "taa": {"rectify": "none", "alpha": 1.0, "history_format": "rgba32f"}})";

// The colour at a pixel centre, rebuilt from the jittered samples, is nearer the unjittered
// frame than the jittered sample is. (A wrong sign of the jitter doubles the offset instead.)
TEST(SeedExtrasUnjitter, CurrentSampleMovesToThePixelCentre) {
  const auto& truth = test::renderOnce(kStillJittered, R"({"jitter": {"pattern": "none"}})", {3});
  const auto& plain = test::renderOnce(kStillJittered, "{}", {3});
  const auto& unjittered =
      test::renderOnce(kStillJittered, R"({"taa": {"unjitter_current": true}})", {3});
  const double ePlain = test::rmse(plain[3].color, truth[3].color);
  const double eUnjittered = test::rmse(unjittered[3].color, truth[3].color);
  test::report("rmse to the unjittered frame, jittered sample", ePlain);
  test::report("rmse to the unjittered frame, unjitter_current", eUnjittered);
  EXPECT_LT(eUnjittered, 0.8 * ePlain);
}

// Alpha 0 with an RGB clamp: frame 1's output is frame 0's (the history) clamped to the box of
// frame 1. Rebuilt on the CPU from frame 1's jittered colour and jitter, the box's eight
// neighbours are the bilinear colours at their pixel centres, the centre tap the raw sample.
TEST(SeedExtrasUnjitter, NeighbourhoodBoxIsBuiltAtThePixelCentres) {
  const char* clamped = R"({"scene": {"builtin": "open_area"},
    "render": {"width": 96, "height": 54}, "script": {"frames": 2},
    "taa": {"rectify": "clamp", "color_space": "rgb", "alpha": 0.0, "history_filter": "bilinear",
            "velocity_sampling": "pixel", "history_format": "rgba32f"}})";
  RenderOptions o;
  o.captures |= {Capture::Current};
  auto run = [&](bool unjitter) -> const test::EffectRun& {
    return test::renderOnce(
        clamped,
        std::string(R"({"taa": {"unjitter_neighborhood": )") + (unjitter ? "true" : "false") + "}}",
        {0, 1}, o);
  };
  const auto& on = run(true);
  const auto& off = run(false);
  const glm::vec2 jitter = script::frameState(on.spec, 1).jitter;
  const Image& cur = test::capturedImage(on[1], Capture::Current);
  const Image& history = on[0].color;
  const int w = cur.width, h = cur.height;
  auto at = [&](int x, int y, int c) {
    return cur.at(std::clamp(x, 0, w - 1), std::clamp(y, 0, h - 1), c);
  };
  auto unjittered = [&](int x, int y, int c) {
    const float tx = float(x) + jitter.x, ty = float(y) + jitter.y;
    const int bx = int(std::floor(tx)), by = int(std::floor(ty));
    const float fx = tx - float(bx), fy = ty - float(by);
    const float top = at(bx, by, c) + (at(bx + 1, by, c) - at(bx, by, c)) * fx;
    const float bottom = at(bx, by + 1, c) + (at(bx + 1, by + 1, c) - at(bx, by + 1, c)) * fx;
    return top + (bottom - top) * fy;
  };
  int mismatchOn = 0, mismatchOff = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) {
        float lo = 1e30f, hi = -1e30f;
        for (int j = -1; j <= 1; ++j)
          for (int i = -1; i <= 1; ++i) {
            const int px = std::clamp(x + i, 0, w - 1), py = std::clamp(y + j, 0, h - 1);
            const float v = (i == 0 && j == 0) ? at(px, py, c) : unjittered(px, py, c);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
          }
        const float expected = std::clamp(history.at(x, y, c), lo, hi);
        const float tolerance = 1e-4f * std::max(1.0f, std::abs(expected));
        mismatchOn += std::abs(on[1].color.at(x, y, c) - expected) > tolerance;
        mismatchOff += std::abs(off[1].color.at(x, y, c) - expected) > tolerance;
      }
  test::report("channels off the CPU's unjittered clamp, unjitter_neighborhood", mismatchOn);
  test::report("channels off the CPU's unjittered clamp, jittered box", mismatchOff);
  EXPECT_EQ(mismatchOn, 0);
  EXPECT_GT(mismatchOff, 100);  // the check can tell the two boxes apart
}

TEST(SeedExtrasUnjitter, RefusedWhereThereIsNoJitterToUndo) {
  for (const char* key : {"unjitter_current", "unjitter_neighborhood"}) {
    const auto problems = test::caseRefusal([&] {
      test::caseFromJson(std::string(R"({"scene": {"builtin": "checkerboard"},
        "jitter": {"pattern": "none"}, "taa": {")") +
                         key + R"(": true}})");
    });
    ASSERT_EQ(problems.size(), 1u) << key;
    EXPECT_NE(problems[0].find("the case jitters"), std::string::npos) << problems[0];
  }
}

// The shader's hash (shaders/taa/output_noise.glsl), for the expected values.
uint32_t noiseHashCpu(uint32_t x, uint32_t y, uint32_t z) {
  return test::hash32(x * 0x8da6b343u ^ y * 0xd8163841u ^ z * 0xcb1ab31fu);
}

// A current of 0.5 at alpha 1 (the history, which got frame 0's noise, has no weight): the
// output is 0.5 plus the noise of its pixel at frame 1, the same in every channel.
TEST(SeedExtrasNoise, IsTheHashOfPixelAndFrameWithinTheAmount) {
  const float amount = 0.25f;
  const std::string json = R"({"scene": {"builtin": "checkerboard"},
    "render": {"width": 16, "height": 8}, "jitter": {"pattern": "none"}, "script": {"frames": 2},
    "taa": {"use_velocity": "all", "velocity_sampling": "pixel", "history_filter": "bilinear",
            "rectify": "none", "alpha": 1.0, "history_format": "rgba32f", "noise": true,
            "noise_amount": 0.25}})";
  test::SyntheticResolve in;
  in.current = Image(16, 8, 4, 0.5f);
  in.history = Image(16, 8, 4, 0.5f);
  const Image out = test::gpuResolve(test::caseFromJson(json, "noise"), in).output;
  double sum = 0.0;
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      const float u = float(noiseHashCpu(uint32_t(x), uint32_t(y), 1u) >> 8) / 16777216.0f;
      const float expected = 0.5f + (2.0f * u - 1.0f) * amount;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(out.at(x, y, c), expected, 1e-6f) << x << "," << y << " channel " << c;
      sum += out.at(x, y, 0) - 0.5f;
    }
  test::report("mean noise over 128 pixels (amount 0.25)", sum / 128.0);
}

// On a scene: each frame gets new noise (alpha 1, so the history does not carry the last
// frame's), bounded by the amount, and a run repeats bit for bit.
TEST(SeedExtrasNoise, ChangesEveryFrameWithinTheAmount) {
  const auto& still =
      test::renderOnce(kStillJittered, R"({"jitter": {"pattern": "none"}})", {2, 3});
  const char* noisy =
      R"({"jitter": {"pattern": "none"}, "taa": {"noise": true, "noise_amount": 0.01}})";
  const auto& a = test::renderOnce(kStillJittered, noisy, {2, 3});
  const auto spec = test::effectCase(kStillJittered, noisy);
  const auto b = test::renderCase(spec, {3});
  EXPECT_TRUE(sameBits(a[3].color, b[3].color));
  EXPECT_LE(test::maxAbs(a[3].color, still[3].color), 0.01 + 1e-6);
  EXPECT_GT(test::meanAbs(a[3].color, still[3].color), 0.003);  // uniform: mean |n| = amount / 2
  EXPECT_GT(test::differing(a[2].color, a[3].color, 1e-4), 160 * 90 / 2);
}

}  // namespace
}  // namespace taa
