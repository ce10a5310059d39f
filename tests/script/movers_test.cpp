#include "script/movers.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

using taa::script::moverState;
using taa::script::repeatedOffset;
using taa::spec::MoverSpec;
using taa::spec::Repeat;
using taa::spec::SpeedUnit;
using taa::spec::TimingSpec;

namespace {

TimingSpec timing(int fps) {
  TimingSpec t;
  t.fps = fps;
  return t;
}

// Start (-2,0.5,0) to end (2,0.5,0): L = 4, one unit per second.
MoverSpec line(Repeat repeat) {
  MoverSpec m;
  m.start = {-2.0f, 0.5f, 0.0f};
  m.end = {2.0f, 0.5f, 0.0f};
  m.speed = 1.0f;
  m.repeat = repeat;
  m.rotation_speed_deg = 0.0f;
  return m;
}

double xAt(const MoverSpec& m, int frame, int fps = 60) {
  return moverState(m, timing(fps), frame).position.x;
}

}  // namespace

TEST(MoverPingPong, GoesToTheEndAndBackAtExactFrames) {
  const MoverSpec m = line(Repeat::PingPong);
  EXPECT_DOUBLE_EQ(xAt(m, 0), -2.0);
  EXPECT_DOUBLE_EQ(xAt(m, 120), 0.0);   // t=2: halfway out
  EXPECT_DOUBLE_EQ(xAt(m, 240), 2.0);   // t=4: at the end
  EXPECT_DOUBLE_EQ(xAt(m, 300), 1.0);   // t=5: one unit on the way back
  EXPECT_DOUBLE_EQ(xAt(m, 360), 0.0);   // t=6: halfway back
  EXPECT_DOUBLE_EQ(xAt(m, 480), -2.0);  // t=8: home again
  EXPECT_DOUBLE_EQ(xAt(m, 540), -1.0);  // t=9: second lap
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 300).position.y, 0.5);
}

TEST(MoverPingPong, PerFrameAgreesWithPerSecondScaledByFps) {
  MoverSpec perSecond = line(Repeat::PingPong);
  perSecond.speed = 1.5f;
  MoverSpec perFrame = perSecond;
  perFrame.speed_unit = SpeedUnit::PerFrame;
  perFrame.speed = 1.5f / 30.0f;
  for (int f = 0; f < 200; f += 7)
    EXPECT_NEAR(xAt(perFrame, f, 30), xAt(perSecond, f, 30), 1e-5) << f;
  // And the per-frame unit really is per frame: fps does not change it.
  EXPECT_NEAR(xAt(perFrame, 40, 30), xAt(perFrame, 40, 120), 1e-12);
  EXPECT_NE(xAt(perSecond, 40, 30), xAt(perSecond, 40, 120));
}

TEST(MoverCyclic, JumpsBackToStartAfterReachingTheEnd) {
  const MoverSpec m = line(Repeat::Cyclic);
  EXPECT_DOUBLE_EQ(xAt(m, 180), 1.0);   // t=3
  EXPECT_DOUBLE_EQ(xAt(m, 240), -2.0);  // t=4 wraps to the start
  EXPECT_DOUBLE_EQ(xAt(m, 300), -1.0);  // t=5 moving forward again, not back
}

TEST(MoverOnce, StopsAtTheEnd) {
  const MoverSpec m = line(Repeat::Once);
  EXPECT_DOUBLE_EQ(xAt(m, 60), -1.0);
  EXPECT_DOUBLE_EQ(xAt(m, 240), 2.0);
  EXPECT_DOUBLE_EQ(xAt(m, 1000), 2.0);
}

TEST(MoverRepeat, ZeroLengthSegmentStaysAtStart) {
  MoverSpec m = line(Repeat::PingPong);
  m.end = m.start;
  const auto st = moverState(m, timing(60), 77);
  EXPECT_EQ(st.position, glm::dvec3(m.start));
  EXPECT_EQ(repeatedOffset(Repeat::Cyclic, 5.0, 0.0), 0.0);
}

TEST(MoverRotation, ContinuousRotationFollowsTime) {
  MoverSpec m = line(Repeat::PingPong);
  m.rotation_speed_deg = 90.0f;
  m.continuous_rotation = true;
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 30).angleDeg, 45.0);
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 300).angleDeg, 90.0 * 5 - 360.0);  // reduced mod 360
}

TEST(MoverRotation, DistanceRotationReversesOnTheWayBack) {
  MoverSpec m = line(Repeat::PingPong);
  m.rotation_speed_deg = 10.0f;  // degrees per unit travelled
  m.continuous_rotation = false;
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 60).angleDeg, 10.0);   // s' = 1 going out
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 240).angleDeg, 40.0);  // s' = 4 at the end
  EXPECT_DOUBLE_EQ(moverState(m, timing(60), 420).angleDeg, 10.0);  // s' = 1 coming back
}

TEST(MoverModel, ComposesTranslateRotateScaleInThatOrder) {
  MoverSpec m = line(Repeat::Once);
  m.size = 2.0f;
  m.rotation_axis = {0.0f, 3.0f, 0.0f};  // not unit: must be normalised
  m.rotation_speed_deg = 90.0f;
  const auto st = moverState(m, timing(60), 60);  // position (-1,0.5,0), 90 degrees about +Y
  const glm::vec4 p = st.model * glm::vec4(1, 0, 0, 1);
  // Scale first (2,0,0), then +90 about +Y turns +X into -Z, then translate.
  EXPECT_NEAR(p.x, -1.0f, 1e-6f);
  EXPECT_NEAR(p.y, 0.5f, 1e-6f);
  EXPECT_NEAR(p.z, -2.0f, 1e-6f);
}

TEST(MoverAnimation, AnimationTimeIsTimeTimesSpeed) {
  MoverSpec m = line(Repeat::Once);
  m.animation_speed = 0.5f;
  EXPECT_DOUBLE_EQ(moverState(m, timing(50), 100).animationTime, 1.0);
}
