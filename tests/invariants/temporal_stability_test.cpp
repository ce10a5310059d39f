#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

namespace {

constexpr int kTemporalStabilityFrames = 10;

// Background plus per-frame noise of the given amplitudes in the reference and the output;
// `velocityPx` on every pixel; pixels with x < moverColumns are flagged as a mover.
std::vector<Frame> sequence(float refAmp, float outAmp, float velocityPx = 0.0f,
                            int moverColumns = 0, float moverAmp = 0.0f) {
  const Image bg = background();
  std::vector<Frame> seq;
  for (int f = 0; f < kTemporalStabilityFrames; ++f) {
    Frame fr;
    fr.frame = f;
    fr.reset = f == 0;
    fr.reference = bg;
    fr.output = bg;
    fr.ids = rgba(0, 0, 0);
    fr.velocity = rgba(velocityPx, 0, 0);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const bool mover = x < moverColumns;
        if (mover) fr.ids.at(x, y, 2) = 1.0f;
        const float amp = mover ? moverAmp : outAmp;
        for (int c = 0; c < 3; ++c) {
          fr.reference.at(x, y, c) += refAmp * (noise(x, y, f, 11) - 0.5f);
          fr.output.at(x, y, c) += amp * (noise(x, y, f, 12) - 0.5f);
        }
      }
    seq.push_back(std::move(fr));
  }
  return seq;
}

}  // namespace

TEST(InvariantTemporalStability, FlickerLikeTheReferencePasses) {
  const auto o = runAll("temporal_stability", staticCase(), sequence(0.1f, 0.1f));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_GT(valueOf(o, "reference_flicker"), 0.005);
  EXPECT_EQ(valueOf(o, "frames"), kTemporalStabilityFrames - 1.0);  // frame 0 resets
}

TEST(InvariantTemporalStability, ThreeTimesTheReferenceFlickerFails) {
  const auto o = runAll("temporal_stability", staticCase(), sequence(0.1f, 0.3f));
  EXPECT_FALSE(o.passed);
  EXPECT_GT(valueOf(o, "flicker"), 2.5 * valueOf(o, "reference_flicker"));
  EXPECT_TRUE(contains(o.detail, " > 1.5 x reference")) << o.detail;
}

// A still reference: the bound is epsilon alone.
TEST(InvariantTemporalStability, EpsilonBoundsFlickerOfAStillReference) {
  EXPECT_TRUE(runAll("temporal_stability", staticCase(), sequence(0.0f, 0.002f)).passed);
  EXPECT_FALSE(runAll("temporal_stability", staticCase(), sequence(0.0f, 0.05f)).passed);
}

// Movers change legitimately; only static pixels count.
TEST(InvariantTemporalStability, MoverPixelsAreNotStatic) {
  const auto o = runAll("temporal_stability", staticCase(), sequence(0.1f, 0.1f, 0.0f, 4, 3.0f));
  EXPECT_TRUE(o.passed) << o.detail;
  EXPECT_EQ(valueOf(o, "mean_static_pixels"), double((kW - 4) * kH));
}

TEST(InvariantTemporalStability, MovingCameraLeavesNoStaticPixels) {
  const auto o = runAll("temporal_stability", staticCase(), sequence(0.1f, 0.1f, 0.5f));
  EXPECT_FALSE(o.passed);
  EXPECT_TRUE(contains(o.detail, "no static pixels")) << o.detail;
}

TEST(InvariantTemporalStability, ResetFramesAreSkipped) {
  auto seq = sequence(0.1f, 0.1f);
  seq[5].reset = true;
  for (int f = 5; f < kTemporalStabilityFrames; ++f)  // a reset (or cut) may jump to a new level
    for (auto& v : seq[size_t(f)].output.data) v += 2.0f;
  EXPECT_TRUE(runAll("temporal_stability", staticCase(), seq).passed);
  seq[5].reset = false;
  EXPECT_FALSE(runAll("temporal_stability", staticCase(), seq).passed);
}

TEST(InvariantTemporalStability, InapplicableWithoutHistoryOrPerPixelBuffers) {
  EXPECT_EQ(inapplicable("temporal_stability", staticCase()), "");
  EXPECT_EQ(inapplicable("temporal_stability", moverCase()), "");  // judged at run time
  auto off = staticCase();
  off.taa.mode = spec::TaaMode::Off;
  EXPECT_TRUE(contains(inapplicable("temporal_stability", off),
                       "temporal_stability needs a temporal history, but taa.mode is off"));
  auto up = staticCase();
  up.render.upsample = 2.0f;
  EXPECT_TRUE(contains(inapplicable("temporal_stability", up), "render.upsample is 2"));
  auto dbg = staticCase();
  dbg.debug.output = spec::DebugOutput::ClampDistance;
  EXPECT_TRUE(contains(inapplicable("temporal_stability", dbg), "debug.output is clamp_distance"));
}

// Stereo TSCMAA writes both eyes side by side, so the output is not the render size; one eye is.
TEST(InvariantTemporalStability, OnlyStereoTscmaaIsRefusedForItsOutputSize) {
  auto stereo = staticCase();
  stereo.taa.mode = spec::TaaMode::Tscmaa;
  stereo.tscmaa.eyes = 2;
  EXPECT_TRUE(contains(inapplicable("temporal_stability", stereo), "tscmaa.eyes 2"));
  auto mono = stereo;
  mono.tscmaa.eyes = 1;
  EXPECT_FALSE(contains(inapplicable("temporal_stability", mono), "tscmaa.eyes"))
      << inapplicable("temporal_stability", mono);
}
