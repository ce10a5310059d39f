#include "script/frame_state.h"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>
#include <stdexcept>
#include <vector>

#include "frame_state_bytes.h"
#include "script/projection.h"

using taa::script::FrameState;
using taa::script::frameState;
using taa::spec::CaseSpec;
using taa::test::cameraBytes;
using taa::test::frameStateBytes;

namespace {

// Everything moving at once, so any hidden state or order dependence shows up.
CaseSpec busyCase() {
  CaseSpec s;
  s.render.width = 320;
  s.render.height = 180;
  s.render.upsample = 2.0f;
  s.render.scale_schedule = {{4, 0.5f}, {8, 0.75f}};
  s.script.fps = 30;
  s.script.frames = 16;
  s.script.reset_history_at = {6};
  s.camera.path.type = taa::spec::CurveType::BSpline3;
  s.camera.path.points = {{0, 2, 8}, {3, 2, 4}, {0, 3, 0}, {-4, 2, 2}, {-2, 1, 6}};
  s.camera.path.cyclic = true;
  s.camera.path.duration_s = 1.0f;
  s.camera.rotate = {20.0f, 40.0f};
  s.camera.bob = {0.1f, 2.0f};
  s.camera.strafe = {1.0f, 0.3f};
  s.camera.cuts = {{10, {5, 1, 5}, {0, 0, 0}}};
  s.movers.resize(2);
  s.movers[1].repeat = taa::spec::Repeat::Cyclic;
  s.movers[1].rotation_speed_deg = 45.0f;
  s.movers[1].shape = taa::spec::MoverShape::Gltf;
  s.movers[1].animation_speed = 2.0f;
  s.jitter.pattern = taa::spec::JitterPattern::Halton;
  return s;
}

}  // namespace

TEST(FrameStatePure, SameFrameTwiceGivesIdenticalBytes) {
  const CaseSpec s = busyCase();
  for (int f : {0, 3, 10, 15})
    EXPECT_EQ(frameStateBytes(frameState(s, f)), frameStateBytes(frameState(s, f))) << f;
}

TEST(FrameStatePure, OutOfOrderEvaluationMatchesInOrder) {
  const CaseSpec s = busyCase();
  std::vector<std::vector<unsigned char>> inOrder;
  for (int f = 0; f < 16; ++f) inOrder.push_back(frameStateBytes(frameState(s, f)));
  for (int i = 0; i < 16; ++i) {
    const int f = (i * 7 + 3) % 16;  // a fixed permutation of 0..15
    EXPECT_EQ(frameStateBytes(frameState(s, f)), inOrder[f]) << f;
  }
  // The frames really differ, so equality above is not vacuous.
  EXPECT_NE(inOrder[1], inOrder[2]);
}

TEST(FrameStatePrev, PreviousCameraAndMoversAreFrameMinusOne) {
  const CaseSpec s = busyCase();
  for (int f = 1; f < 16; ++f) {
    if (f == 10) continue;  // the cut frame, tested below
    const FrameState now = frameState(s, f), before = frameState(s, f - 1);
    EXPECT_EQ(cameraBytes(now.prevCamera), cameraBytes(before.camera)) << f;
    EXPECT_EQ(now.prevMovers, before.movers) << f;
  }
  const FrameState first = frameState(s, 0);
  EXPECT_EQ(cameraBytes(first.prevCamera), cameraBytes(first.camera));
  EXPECT_EQ(first.prevMovers, first.movers);
}

TEST(FrameStateCut, CutFrameFlagsResetAndHasNoCameraMotion) {
  CaseSpec s = busyCase();
  s.camera.path.points.clear();  // let the cut's pose show through
  const FrameState cut = frameState(s, 10);
  EXPECT_TRUE(cut.cameraCut);
  EXPECT_TRUE(cut.resetHistory);
  EXPECT_EQ(cameraBytes(cut.prevCamera), cameraBytes(cut.camera));
  EXPECT_NE(cameraBytes(cut.camera), cameraBytes(frameState(s, 9).camera));
  EXPECT_EQ(cut.prevMovers, frameState(s, 9).movers);  // objects keep moving through a cut
  EXPECT_FALSE(frameState(s, 11).cameraCut);
}

TEST(FrameStateReset, ResetsAtFrameZeroCutsAndListedFramesOnly) {
  const CaseSpec s = busyCase();
  for (int f = 0; f < 16; ++f)
    EXPECT_EQ(frameState(s, f).resetHistory, f == 0 || f == 6 || f == 10) << f;
}

TEST(FrameStateSize, RenderSizeFollowsUpsampleAndScaleSchedule) {
  const CaseSpec s = busyCase();  // 320x180 / 2 = 160x90
  EXPECT_EQ(frameState(s, 0).renderSize, glm::ivec2(160, 90));
  EXPECT_EQ(frameState(s, 0).renderScale, 1.0f);
  EXPECT_EQ(frameState(s, 4).renderSize, glm::ivec2(80, 45));
  EXPECT_EQ(frameState(s, 7).renderScale, 0.5f);
  EXPECT_EQ(frameState(s, 8).renderSize, glm::ivec2(120, 68));  // 67.5 rounds up
  CaseSpec tiny = s;
  tiny.render.width = 3;
  tiny.render.height = 1;
  tiny.render.scale_schedule = {{0, 0.05f}};
  EXPECT_EQ(frameState(tiny, 0).renderSize, glm::ivec2(1, 1));
}

TEST(FrameStateCamera, AspectUsesOutputSizeNotScaledRenderSize) {
  CaseSpec s = busyCase();
  s.render.width = 300;  // 150x90 at upsample 2; 75x45 at scale 0.5, aspect 5/3 throughout
  const FrameState fs = frameState(s, 5);
  EXPECT_FLOAT_EQ(fs.camera.aspect, 300.0f / 180.0f);
  EXPECT_FLOAT_EQ(fs.camera.fovY, glm::radians(s.camera.fov_y_deg));
  EXPECT_EQ(fs.camera.viewProjection, fs.camera.projection * fs.camera.view);
}

TEST(FrameStateJitter, JitteredProjectionMovesTheImageByTheJitterInRenderPixels) {
  const CaseSpec s = busyCase();
  for (int f : {1, 5, 9}) {
    const FrameState fs = frameState(s, f);
    ASSERT_NE(fs.jitter, glm::vec2(0.0f));
    const glm::dvec3 world(0.3, 0.7, -0.4);
    const glm::dvec3 a = taa::script::worldToPixel(fs.camera.viewProjection, world, fs.renderSize);
    const glm::dvec3 b =
        taa::script::worldToPixel(fs.jitteredProjection * fs.camera.view, world, fs.renderSize);
    EXPECT_NEAR(b.x - a.x, fs.jitter.x, 1e-3) << f;
    EXPECT_NEAR(b.y - a.y, fs.jitter.y, 1e-3) << f;
  }
}

TEST(FrameStateMovers, OneTransformAndAnimationTimePerMover) {
  const CaseSpec s = busyCase();
  const FrameState fs = frameState(s, 15);
  ASSERT_EQ(fs.movers.size(), 2u);
  ASSERT_EQ(fs.prevMovers.size(), 2u);
  ASSERT_EQ(fs.moverAnimTime.size(), 2u);
  EXPECT_DOUBLE_EQ(fs.time, 0.5);
  EXPECT_DOUBLE_EQ(fs.moverAnimTime[1], 1.0);
  EXPECT_NE(fs.movers[0], fs.prevMovers[0]);
}

TEST(FrameStateArgs, NegativeFrameIsRejected) {
  EXPECT_THROW(frameState(busyCase(), -1), std::out_of_range);
}
