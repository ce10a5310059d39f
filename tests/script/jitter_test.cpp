#include "script/jitter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "script/projection.h"

using taa::script::applyJitter;
using taa::script::halton;
using taa::script::jitterOffset;
using taa::script::jitterPatternLength;
using taa::script::jitterStep;
using taa::script::reversedZPerspective;
using taa::script::worldToPixel;
using taa::spec::JitterPattern;
using taa::spec::JitterSpec;

namespace {

JitterSpec pattern(JitterPattern p) {
  JitterSpec j;
  j.pattern = p;
  return j;
}

void expectOffset(const JitterSpec& j, int frame, float x, float y) {
  const glm::vec2 o = jitterOffset(j, frame);
  EXPECT_NEAR(o.x, x, 1e-6f) << "frame " << frame;
  EXPECT_NEAR(o.y, y, 1e-6f) << "frame " << frame;
}

}  // namespace

TEST(JitterHalton, FirstEightBase2AreBitReversedHalves) {
  const double expected[] = {1 / 2., 1 / 4., 3 / 4., 1 / 8., 5 / 8., 3 / 8., 7 / 8., 1 / 16.};
  for (uint32_t i = 1; i <= 8; ++i) EXPECT_EQ(halton(i, 2), expected[i - 1]) << i;
}

TEST(JitterHalton, FirstEightBase3AreDigitReversedThirds) {
  const double expected[] = {1 / 3., 2 / 3., 1 / 9., 4 / 9., 7 / 9., 2 / 9., 5 / 9., 8 / 9.};
  for (uint32_t i = 1; i <= 8; ++i) EXPECT_DOUBLE_EQ(halton(i, 3), expected[i - 1]) << i;
}

TEST(JitterHalton, IndexZeroIsZeroWhichIsWhyThePatternSkipsIt) {
  EXPECT_EQ(halton(0, 2), 0.0);
  EXPECT_EQ(halton(0, 3), 0.0);
}

TEST(JitterPatterns, HaltonUsesIndicesOneToLengthCentredOnThePixel) {
  JitterSpec j = pattern(JitterPattern::Halton);
  j.length = 8;
  expectOffset(j, 0, 0.0f, 1 / 3.f - 0.5f);             // index 1
  expectOffset(j, 1, -0.25f, 2 / 3.f - 0.5f);           // index 2
  expectOffset(j, 7, 1 / 16.f - 0.5f, 8 / 9.f - 0.5f);  // index 8
  expectOffset(j, 8, 0.0f, 1 / 3.f - 0.5f);             // wraps to index 1
}

TEST(JitterPatterns, HaltonLengthSetsThePeriod) {
  JitterSpec j = pattern(JitterPattern::Halton);
  j.length = 16;
  EXPECT_EQ(jitterPatternLength(j), 16);
  EXPECT_NE(jitterOffset(j, 8), jitterOffset(j, 0));
  EXPECT_EQ(jitterOffset(j, 16), jitterOffset(j, 0));
}

TEST(JitterPatterns, Uniform4VisitsTheGridInRowOrder) {
  const JitterSpec j = pattern(JitterPattern::Uniform4);
  expectOffset(j, 0, -0.25f, -0.25f);
  expectOffset(j, 1, 0.25f, -0.25f);
  expectOffset(j, 2, -0.25f, 0.25f);
  expectOffset(j, 3, 0.25f, 0.25f);
  expectOffset(j, 4, -0.25f, -0.25f);
}

TEST(JitterPatterns, Symmetric2AlternatesOppositeQuarterPixels) {
  const JitterSpec j = pattern(JitterPattern::Symmetric2);
  expectOffset(j, 0, -0.25f, -0.25f);
  expectOffset(j, 1, 0.25f, 0.25f);
  expectOffset(j, 2, -0.25f, -0.25f);
}

TEST(JitterPatterns, Legacy2AlternatesZeroAndHalfPixel) {
  const JitterSpec j = pattern(JitterPattern::Legacy2);
  expectOffset(j, 0, 0.0f, 0.0f);
  expectOffset(j, 1, 0.5f, 0.5f);
  expectOffset(j, 3, 0.5f, 0.5f);
}

TEST(JitterPatterns, ManualCyclesThroughGivenPoints) {
  JitterSpec j = pattern(JitterPattern::Manual);
  j.points = {{0.1f, -0.2f}, {0.3f, 0.4f}, {-0.5f, 0.5f}};
  expectOffset(j, 0, 0.1f, -0.2f);
  expectOffset(j, 2, -0.5f, 0.5f);
  expectOffset(j, 4, 0.3f, 0.4f);
}

TEST(JitterPatterns, NoneIsAlwaysZero) {
  const JitterSpec j = pattern(JitterPattern::None);
  for (int f = 0; f < 5; ++f) expectOffset(j, f, 0.0f, 0.0f);
}

TEST(JitterStep, SlowdownHoldsEachStepForKFrames) {
  JitterSpec j = pattern(JitterPattern::Uniform4);
  j.slowdown = 3;
  const int expected[] = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 0};
  for (int f = 0; f < 13; ++f) EXPECT_EQ(jitterStep(j, f), expected[f]) << f;
  expectOffset(j, 4, 0.25f, -0.25f);
}

TEST(JitterStep, LockPinsOneStepModuloTheLength) {
  JitterSpec j = pattern(JitterPattern::Uniform4);
  j.lock = 2;
  for (int f = 0; f < 6; ++f) expectOffset(j, f, -0.25f, 0.25f);
  j.lock = 5;  // 5 mod 4
  for (int f = 0; f < 6; ++f) EXPECT_EQ(jitterStep(j, f), 1);
  j.lock = 0;  // the first step is a step like any other; -1 (the default) is no lock
  for (int f = 0; f < 6; ++f) EXPECT_EQ(jitterStep(j, f), 0) << f;
}

TEST(JitterTransform, RotateTurnsXTowardsYAboutThePixelCentre) {
  JitterSpec j = pattern(JitterPattern::Manual);
  j.points = {{0.25f, 0.0f}};
  j.rotate_deg = 90.0f;
  expectOffset(j, 0, 0.0f, 0.25f);
  j.rotate_deg = 45.0f;
  const float r = 0.25f / std::sqrt(2.0f);
  expectOffset(j, 0, r, r);
}

TEST(JitterTransform, ScaleMultipliesAfterRotation) {
  JitterSpec j = pattern(JitterPattern::Symmetric2);
  j.scale = 2.0f;
  expectOffset(j, 1, 0.5f, 0.5f);
  j.rotate_deg = 180.0f;
  expectOffset(j, 1, -0.5f, -0.5f);
  j.scale = 0.0f;
  expectOffset(j, 1, 0.0f, 0.0f);
}

TEST(JitterProjection, JitteredProjectionMovesProjectedPointsByExactlyTheOffset) {
  const glm::ivec2 size(320, 180);
  const glm::mat4 proj = reversedZPerspective(glm::radians(60.0f), 16.0f / 9.0f, 0.1f, 1000.0f);
  const glm::mat4 view = glm::lookAt(glm::vec3(1, 2, 5), glm::vec3(0, 0.5f, 0), glm::vec3(0, 1, 0));
  const glm::vec2 offsets[] = {{0.25f, -0.25f}, {-0.5f, 0.5f}, {0.37f, 0.11f}, {3.0f, -2.0f}};
  const glm::dvec3 points[] = {{0, 0.5, 0}, {-2, 1, -3}, {3, -1, 1}, {0.3, 4, -40}};
  for (const glm::vec2 o : offsets) {
    const glm::mat4 jittered = applyJitter(proj, o, size);
    for (const glm::dvec3& p : points) {
      const glm::dvec3 a = worldToPixel(proj * view, p, size);
      const glm::dvec3 b = worldToPixel(jittered * view, p, size);
      EXPECT_NEAR(b.x - a.x, o.x, 1e-4) << "offset " << o.x << "," << o.y;
      EXPECT_NEAR(b.y - a.y, o.y, 1e-4) << "offset " << o.x << "," << o.y;
      EXPECT_NEAR(b.z, a.z, 1e-7);  // jitter never changes depth
    }
  }
}

TEST(JitterProjection, OffsetIsInPixelsOfTheGivenTarget) {
  // Same offset on a target half as wide: the NDC shift doubles, the pixel shift stays.
  const glm::mat4 proj = reversedZPerspective(1.0f, 1.0f, 0.1f, 100.0f);
  const glm::vec2 o(0.5f, 0.25f);
  for (glm::ivec2 size : {glm::ivec2(64, 64), glm::ivec2(32, 96)}) {
    const glm::dvec3 a = worldToPixel(proj, {0.2, -0.1, -3}, size);
    const glm::dvec3 b = worldToPixel(applyJitter(proj, o, size), {0.2, -0.1, -3}, size);
    EXPECT_NEAR(b.x - a.x, o.x, 1e-5);
    EXPECT_NEAR(b.y - a.y, o.y, 1e-5);
  }
}
