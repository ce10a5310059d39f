// The resolve stores its half-float history rounded to nearest, ties to even, whatever the
// driver's store rounding: lavapipe rounds half stores toward zero, and in the feedback loop
// that bias compounded into a darker converged image.
#include <gtest/gtest.h>

#include "core/image_io.h"
#include "support/gpu.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

constexpr float kUlp = 1.0f / 1024.0f;  // half ulp in [1, 2)

// History 1, current 1 + k ulps, alpha 1/4: the blend is exactly 1 + k/4 ulps in float, a
// fraction of a half ulp for every k not divisible by 4.
test::GpuResolveResult quarterStepResolve(const char* historyFormat) {
  const std::string json = std::string(R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 8, "height": 2},
    "jitter": {"pattern": "none"},
    "script": {"frames": 2},
    "taa": {"use_velocity": "all", "velocity_sampling": "pixel", "history_filter": "bilinear",
            "rectify": "none", "alpha": 0.25, "history_format": ")") +
                           historyFormat + R"("}})";
  test::SyntheticResolve in;
  in.current = Image(8, 2, 4, 1.0f);
  in.history = Image(8, 2, 4, 1.0f);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 3; ++c) in.current.at(x, y, c) = 1.0f + float(x) * kUlp;
  return test::gpuResolve(test::caseFromJson(json, "history_rounding"), in);
}

TEST(HistoryStoreRounding, HalfHistoryRoundsBlendToNearestEven) {
  const auto r = quarterStepResolve("rgba16f");
  // k/4 ulps rounded to nearest, ties to even: 0, 0.25, 0.5, 0.75, 1, 1.25, 1.5, 1.75
  const int expectedUlps[8] = {0, 0, 0, 1, 1, 1, 2, 2};
  for (int x = 0; x < 8; ++x)
    for (int c = 0; c < 3; ++c) {
      const float exact = 1.0f + float(x) * 0.25f * kUlp;
      EXPECT_EQ(r.output.at(x, 1, c), 1.0f + float(expectedUlps[x]) * kUlp)
          << "pixel " << x << " channel " << c << ": blend " << exact;
      EXPECT_EQ(r.output.at(x, 1, c), halfBitsToFloat(floatToHalfBits(exact)));
    }
}

TEST(HistoryStoreRounding, FloatHistoryKeepsTheExactBlend) {
  const auto r = quarterStepResolve("rgba32f");
  for (int x = 0; x < 8; ++x)
    EXPECT_EQ(r.output.at(x, 0, 0), 1.0f + float(x) * 0.25f * kUlp) << "pixel " << x;
}

}  // namespace
}  // namespace taa
