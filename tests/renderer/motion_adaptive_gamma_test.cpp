// Motion-adaptive variance gamma (Intel's TAA sample, GameTechDev/TAA TAAResolve.hlsl): the
// gamma of variance clipping is lerped from MIN_VARIANCE_GAMMA 0.75 under motion to
// MAX_VARIANCE_GAMMA 2 at rest by the squared velocity confidence 1 - speed / limit, "to
// ensure when no motion specular highlights not cut by the variance clipping". These tests run
// the real resolve on a synthetic frame whose history sits inside the 3x3 min/max box but
// outside mean +- 0.75 sigma, so the gamma decides how much of it survives.
#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

constexpr int kMotionGammaW = 24, kMotionGammaH = 16;
constexpr float kMotionGammaHistory = 0.97f;

// A black and white checkerboard (3x3 mean 4/9 or 5/9, sigma 0.5) and a flat history of 0.97:
// inside mean + 2 sigma everywhere, so gamma 2 leaves the min/max box and keeps it; gamma 1
// clamps it to 0.94 around black pixels, gamma 0.75 to 0.82 and 0.93.
test::SyntheticResolve motionGammaFrame(glm::vec2 velocityPx) {
  test::SyntheticResolve in;
  in.current = Image(kMotionGammaW, kMotionGammaH, 4, 1.0f);
  in.history = Image(kMotionGammaW, kMotionGammaH, 4, 1.0f);
  for (int y = 0; y < kMotionGammaH; ++y)
    for (int x = 0; x < kMotionGammaW; ++x)
      for (int c = 0; c < 3; ++c) {
        in.current.at(x, y, c) = (x + y) % 2 == 0 ? 0.0f : 1.0f;
        in.history.at(x, y, c) = kMotionGammaHistory;
      }
  in.velocityPx = velocityPx;
  return in;
}

spec::CaseSpec motionGammaCase(bool adaptive, float gamma) {
  spec::CaseSpec spec = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "render": {"width": 24, "height": 16},
    "jitter": {"pattern": "none"},
    "script": {"frames": 2},
    "taa": {"mode": "full", "use_velocity": "all", "velocity_sampling": "pixel",
            "history_filter": "bilinear", "rectify": "clamp", "color_space": "rgb",
            "variance_clip": true, "alpha": 0.1}
  })",
                                           "motion_adaptive_gamma");
  spec.taa.motion_adaptive_gamma = adaptive;
  spec.taa.variance_gamma = gamma;
  spec.taa.variance_gamma_velocity_px = 4.0f;
  return spec;
}

bool motionGammaSame(const Image& a, const Image& b) {
  return a.data == b.data;
}

// Mean distance of the output from the history over pixels whose history stays on screen.
double motionGammaLost(const Image& out, int margin) {
  double sum = 0.0;
  int n = 0;
  for (int y = margin; y < kMotionGammaH - margin; ++y)
    for (int x = margin; x < kMotionGammaW - margin; ++x) {
      sum += std::fabs(out.at(x, y, 0) - kMotionGammaHistory);
      ++n;
    }
  return sum / n;
}

// At rest the gamma is variance_gamma_static (2); at variance_gamma_velocity_px or faster it is
// variance_gamma_moving (0.75); halfway the confidence 0.5, squared, gives 0.75 + 1.25 / 4.
TEST(MotionAdaptiveGamma, LerpsFromStaticToMovingGammaBySquaredVelocityConfidence) {
  struct Step {
    glm::vec2 velocity;
    float gamma;
  };
  for (const Step& step : {Step{{0.0f, 0.0f}, 2.0f}, Step{{2.0f, 0.0f}, 1.0625f},
                           Step{{4.0f, 0.0f}, 0.75f}, Step{{0.0f, 6.0f}, 0.75f}}) {
    const test::SyntheticResolve in = motionGammaFrame(step.velocity);
    const Image adaptive = test::gpuResolve(motionGammaCase(true, 1.0f), in).output;
    const Image fixed = test::gpuResolve(motionGammaCase(false, step.gamma), in).output;
    EXPECT_TRUE(motionGammaSame(adaptive, fixed))
        << "velocity " << step.velocity.x << "," << step.velocity.y << " should clip with gamma "
        << step.gamma;
  }
}

// What the seed says it is for: a still pixel keeps its history (the highlight a tight box would
// cut), a moving one is clipped harder than with the default gamma 1 (its trail goes).
TEST(MotionAdaptiveGamma, StillPixelsKeepHistoryThatMovingPixelsLose) {
  const Image still =
      test::gpuResolve(motionGammaCase(true, 1.0f), motionGammaFrame({0.0f, 0.0f})).output;
  const Image stillFixed =
      test::gpuResolve(motionGammaCase(false, 1.0f), motionGammaFrame({0.0f, 0.0f})).output;
  const Image moving =
      test::gpuResolve(motionGammaCase(true, 1.0f), motionGammaFrame({4.0f, 0.0f})).output;
  const Image movingFixed =
      test::gpuResolve(motionGammaCase(false, 1.0f), motionGammaFrame({4.0f, 0.0f})).output;
  const int margin = 5;  // the history moved 4 pixels: the border has none
  // By the numbers above: 0.050 against 0.064 at rest, 0.135 against 0.064 in motion.
  EXPECT_LT(motionGammaLost(still, margin), motionGammaLost(stillFixed, margin) - 0.01);
  EXPECT_GT(motionGammaLost(moving, margin), motionGammaLost(movingFixed, margin) + 0.05);
}

}  // namespace
}  // namespace taa
