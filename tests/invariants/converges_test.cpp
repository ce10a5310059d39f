#include <cmath>

#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

// output_f = reference + error(f) * zero-mean noise, so RMSE is proportional to error(f).
template <class ErrorOf>
std::vector<Frame> sequenceConverges(int frames, ErrorOf errorOf, int resetAt = -1) {
  const Image ref = background();
  std::vector<Frame> seq;
  for (int f = 0; f < frames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0 || f == resetAt;
    fr.reference = ref;
    fr.output = ref;
    const float e = errorOf(f);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        for (int c = 0; c < 3; ++c)
          fr.output.at(x, y, c) += e * (2.0f * noise(x, y, f, uint32_t(c)) - 1.0f);
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantConverges, DecayingErrorPasses) {
  const auto o = runAll("converges", staticCase(),
                        sequenceConverges(16, [](int f) { return 0.2f * std::pow(0.85f, f); }));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_LT(valueOf(o, "last_rmse"), valueOf(o, "bound"));
  EXPECT_EQ(valueOf(o, "frames"), 16.0);
}

TEST(InvariantConverges, GrowingErrorFails) {
  const auto o = runAll("converges", staticCase(),
                        sequenceConverges(16, [](int f) { return 0.02f * float(1 + f); }));
  EXPECT_FALSE(o.passed);
  EXPECT_GT(valueOf(o, "last_quarter_mean"), valueOf(o, "first_quarter_mean"));
  EXPECT_TRUE(contains(o.detail, "last-quarter mean")) << o.detail;
}

// Noise that never accumulates away: the end is not below ratio x the start.
TEST(InvariantConverges, FlatErrorFailsTheRatio) {
  const auto o = runAll("converges", staticCase(), sequenceConverges(16, [](int) { return 0.1f; }));
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, " > 0.6 x first")) << o.detail;
}

// A reset restarts accumulation: the check judges the run after the last one.
TEST(InvariantConverges, HistoryResetRestartsTheRun) {
  const auto seq = sequenceConverges(
      24, [](int f) { return 0.2f * std::pow(0.85f, f < 8 ? f : f - 8); }, 8);
  const auto o = runAll("converges", staticCase(), seq);
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "frames"), 16.0);
  EXPECT_TRUE(contains(o.detail, "frames 8..23")) << o.detail;
}

TEST(InvariantConverges, FromFrameSkipsWarmUp) {
  // Worse for 4 frames, then converging: fails from 0 (trend), passes from 4.
  const auto seq =
      sequenceConverges(20, [](int f) { return f < 4 ? 0.01f : 0.2f * std::pow(0.85f, f - 4); });
  auto s = staticCase();
  EXPECT_FALSE(runAll("converges", s, seq).passed);
  s.checks.from_frame = 4;
  EXPECT_TRUE(runAll("converges", s, seq).passed);
}

TEST(InvariantConverges, TooFewFramesFails) {
  const auto o = runAll("converges", staticCase(), sequenceConverges(3, [](int) { return 0.0f; }));
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "needs at least 4")) << o.detail;
}

TEST(InvariantConverges, InapplicableWhenAnythingMovesOrNothingAccumulates) {
  EXPECT_EQ(inapplicable("converges", staticCase()), "");
  auto expectReason = [](auto mutate, const std::string& part) {
    auto s = staticCase();
    mutate(s);
    const auto why = inapplicable("converges", s);
    EXPECT_TRUE(contains(why, part)) << "'" << why << "' lacks '" << part << "'";
  };
  expectReason([](auto& s) { s.camera.strafe.speed = 2.0f; },
               "converges needs a static scene, but camera.strafe.speed is 2; remove it from "
               "checks.invariants");
  expectReason(
      [](auto& s) {
        s.camera.path.points = {{0, 0, 0}, {1, 0, 0}};
      },
      "camera.path has 2 points");
  expectReason([](auto& s) { s.camera.rotate.yaw_deg_per_s = 10.0f; },
               "camera.rotate.yaw_deg_per_s is 10");
  expectReason([](auto& s) { s.camera.bob.amplitude = 0.1f; }, "camera.bob.amplitude is 0.1");
  expectReason([](auto& s) { s.camera.cuts.emplace_back(); }, "camera.cuts has 1 cut(s)");
  // A glTF scene that animates itself moves; held (animation_speed 0), or without animations, not.
  auto gltf = [](const char* scene, float speed) {
    auto s = staticCase();
    s.file = std::string(TAA_SOURCE_DIR) + "/cases/t.json";
    s.scene.gltf = scene;
    s.scene.animation_speed = speed;
    return s;
  };
  expectReason([&](auto& s) { s = gltf("scenes/animated.gltf", 1.0f); },
               "the glTF scene's own animations play");
  EXPECT_EQ(inapplicable("converges", gltf("scenes/animated.gltf", 0.0f)), "");
  EXPECT_EQ(inapplicable("converges", gltf("scenes/box.glb", 1.0f)), "");
  EXPECT_EQ(inapplicable("converges", gltf("scenes/missing.gltf", 1.0f)), "");
  expectReason([](auto& s) { s.movers.emplace_back(); }, "movers[0].speed is 1");
  expectReason(
      [](auto& s) {
        s.movers.emplace_back();
        s.movers[0].speed = 0.0f;
        s.movers[0].rotation_speed_deg = 30.0f;
      },
      "movers[0].rotation_speed_deg is 30");
  expectReason([](auto& s) { s.taa.mode = spec::TaaMode::PassThrough; },
               "taa.mode is pass_through");
  expectReason([](auto& s) { s.jitter.pattern = spec::JitterPattern::None; },
               "jitter.pattern is none");
  expectReason([](auto& s) { s.jitter.lock = 2; }, "jitter.lock is 2");
  // A mover that stands still does not disturb a static scene.
  auto parked = staticCase();
  parked.movers.emplace_back();
  parked.movers[0].speed = 0.0f;
  EXPECT_EQ(inapplicable("converges", parked), "");
}
