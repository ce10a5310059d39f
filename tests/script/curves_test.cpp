#include "script/curves.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <glm/geometric.hpp>
#include <vector>

using taa::script::evaluateCurve;
using taa::script::kArcLengthSamples;
using taa::script::Path;
using taa::script::pathTimeFraction;
using taa::spec::CurveType;
using taa::spec::PathSpec;

namespace {

constexpr CurveType kAllTypes[] = {CurveType::Bezier, CurveType::BSpline2, CurveType::BSpline3,
                                   CurveType::CatmullRom};

// Bunched at one end, spread at the other: a raw parameterisation moves at very
// different speeds along it, which is what the constant-speed tests need.
const std::vector<glm::vec3> kUneven = {{0, 0, 0},  {0.2f, 0, 0.1f}, {0.5f, 0.3f, 0},
                                        {4, 0, -1}, {9, 1, 2},       {10, 0, 8}};

PathSpec makePath(CurveType type, bool cyclic, bool constantSpeed = false,
                  std::vector<glm::vec3> points = kUneven) {
  PathSpec p;
  p.type = type;
  p.points = std::move(points);
  p.cyclic = cyclic;
  p.constant_speed = constantSpeed;
  p.duration_s = 4.0f;
  return p;
}

double dist(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(a - b);
}

// Arc length between two times, integrated finely enough to be exact to 1e-6.
double arcLength(const Path& path, double t0, double t1) {
  constexpr int kSub = 400;
  double len = 0.0;
  glm::dvec3 prev = path.atTime(t0).position;
  for (int i = 1; i <= kSub; ++i) {
    const glm::dvec3 p = path.atTime(t0 + (t1 - t0) * i / kSub).position;
    len += dist(p, prev);
    prev = p;
  }
  return len;
}

// Ratio of the longest to the shortest of `steps` equal time steps over one traversal.
double stepLengthSpread(const PathSpec& spec, int steps) {
  const Path path(spec);
  std::vector<double> lengths;
  for (int i = 0; i < steps; ++i) {
    const double d = spec.duration_s;
    lengths.push_back(arcLength(path, d * i / steps, d * (i + 1) / steps));
  }
  const auto [lo, hi] = std::minmax_element(lengths.begin(), lengths.end());
  return *hi / *lo;
}

}  // namespace

TEST(CurveEndpoints, InterpolatingTypesStartAtFirstAndEndAtLastPoint) {
  for (CurveType type : kAllTypes) {
    const PathSpec p = makePath(type, false);
    EXPECT_LT(dist(evaluateCurve(p, 0.0).position, glm::dvec3(kUneven.front())), 1e-12)
        << int(type);
    EXPECT_LT(dist(evaluateCurve(p, 1.0).position, glm::dvec3(kUneven.back())), 1e-12) << int(type);
  }
}

TEST(CurveShape, QuadraticBezierMidpointIsQuarterHalfQuarterBlend) {
  const PathSpec p = makePath(CurveType::Bezier, false, false, {{0, 0, 0}, {2, 4, 0}, {4, 0, 8}});
  const glm::dvec3 expected =
      0.25 * glm::dvec3(0, 0, 0) + 0.5 * glm::dvec3(2, 4, 0) + 0.25 * glm::dvec3(4, 0, 8);
  EXPECT_LT(dist(evaluateCurve(p, 0.5).position, expected), 1e-12);
}

TEST(CurveShape, CyclicBezierAppendsFirstPointAsLastControlPoint) {
  // Closing (0,0,0),(2,0,0) gives the quadratic (0,0,0),(2,0,0),(0,0,0): at u=0.5
  // it reaches 0.5*(2,0,0), not the open line's midpoint (1,0,0) at a different u.
  const PathSpec p = makePath(CurveType::Bezier, true, false, {{0, 0, 0}, {2, 0, 0}});
  EXPECT_LT(dist(evaluateCurve(p, 0.5).position, glm::dvec3(1, 0, 0)), 1e-12);
  EXPECT_LT(dist(evaluateCurve(p, 0.25).position, glm::dvec3(0.75, 0, 0)), 1e-12);
}

TEST(CurveShape, ClampedCubicBSplineOnFourPointsEqualsCubicBezier) {
  const std::vector<glm::vec3> pts = {{0, 0, 0}, {1, 3, 0}, {3, -1, 2}, {4, 0, 0}};
  const PathSpec bs = makePath(CurveType::BSpline3, false, false, pts);
  const PathSpec bz = makePath(CurveType::Bezier, false, false, pts);
  for (double u : {0.1, 0.3, 0.5, 0.77}) {
    EXPECT_LT(dist(evaluateCurve(bs, u).position, evaluateCurve(bz, u).position), 1e-12) << u;
  }
}

TEST(CurveShape, PeriodicCubicBSplineKnotValueIsOneFourOneAverage) {
  const std::vector<glm::vec3> pts = {{0, 0, 0}, {6, 0, 0}, {6, 6, 0}, {0, 6, 0}, {-3, 3, 3}};
  const PathSpec p = makePath(CurveType::BSpline3, true, false, pts);
  // u=0 is the start of the first span, whose window is points 0,1,2,3.
  const glm::dvec3 expected =
      (glm::dvec3(pts[0]) + 4.0 * glm::dvec3(pts[1]) + glm::dvec3(pts[2])) / 6.0;
  EXPECT_LT(dist(evaluateCurve(p, 0.0).position, expected), 1e-12);
  const glm::dvec3 second =
      (glm::dvec3(pts[1]) + 4.0 * glm::dvec3(pts[2]) + glm::dvec3(pts[3])) / 6.0;
  EXPECT_LT(dist(evaluateCurve(p, 0.2).position, second), 1e-12);
}

TEST(CurveShape, CatmullRomPassesThroughEveryControlPoint) {
  for (bool cyclic : {false, true}) {
    const PathSpec p = makePath(CurveType::CatmullRom, cyclic);
    const int segments = static_cast<int>(kUneven.size()) - (cyclic ? 0 : 1);
    for (size_t i = 0; i < kUneven.size(); ++i)
      EXPECT_LT(dist(evaluateCurve(p, double(i) / segments).position, glm::dvec3(kUneven[i])),
                1e-12)
          << "cyclic " << cyclic << " point " << i;
  }
}

TEST(CurveContinuity, NoPositionJumpAcrossSegmentJoins) {
  constexpr double eps = 1e-9;
  for (CurveType type : kAllTypes)
    for (bool cyclic : {false, true}) {
      const PathSpec p = makePath(type, cyclic);
      // Every join of every type lies on a multiple of 1/60 for 6 points (segments
      // 3, 4, 5 or 6); the grid also covers interior points.
      for (int k = 1; k < 60; ++k) {
        const double u = k / 60.0;
        const double jump =
            dist(evaluateCurve(p, u - eps).position, evaluateCurve(p, u + eps).position);
        EXPECT_LT(jump, 1e-6) << "type " << int(type) << " cyclic " << cyclic << " u " << u;
      }
    }
}

TEST(CurveContinuity, TangentIsTheDerivativeOfPosition) {
  constexpr double h = 1e-6;
  for (CurveType type : kAllTypes)
    for (bool cyclic : {false, true}) {
      const PathSpec p = makePath(type, cyclic);
      for (double u : {0.05, 0.31, 0.5, 0.72, 0.95}) {
        const glm::dvec3 fd =
            (evaluateCurve(p, u + h).position - evaluateCurve(p, u - h).position) / (2 * h);
        const glm::dvec3 t = evaluateCurve(p, u).tangent;
        EXPECT_LT(dist(fd, t), 1e-4 * (1.0 + glm::length(t))) << "type " << int(type) << " u " << u;
      }
    }
}

TEST(CurveConstantSpeed, EqualTimeStepsCoverEqualArcLengthsWithinOnePercent) {
  for (CurveType type : kAllTypes)
    for (bool cyclic : {false, true})
      EXPECT_LT(stepLengthSpread(makePath(type, cyclic, true), 16), 1.01)
          << "type " << int(type) << " cyclic " << cyclic;
}

TEST(CurveConstantSpeed, WithoutReparameterisationUnevenPolygonGivesUnequalSteps) {
  // Proves the previous test can fail: the same paths without arc-length mapping.
  for (CurveType type : kAllTypes)
    for (bool cyclic : {false, true})
      EXPECT_GT(stepLengthSpread(makePath(type, cyclic, false), 16), 1.2)
          << "type " << int(type) << " cyclic " << cyclic;
}

TEST(CurveConstantSpeed, ArcFractionInvertsTheTable) {
  const Path path(makePath(CurveType::CatmullRom, false, true));
  ASSERT_GT(path.length(), 0.0);
  EXPECT_EQ(path.parameterAtArcFraction(0.0), 0.0);
  EXPECT_EQ(path.parameterAtArcFraction(1.0), 1.0);
  // Measure the length up to the returned parameter independently of the table.
  const double uHalf = path.parameterAtArcFraction(0.5);
  const PathSpec& spec = path.spec();
  double len = 0.0;
  glm::dvec3 prev = evaluateCurve(spec, 0.0).position;
  for (int i = 1; i <= kArcLengthSamples; ++i) {
    const glm::dvec3 q = evaluateCurve(spec, uHalf * i / kArcLengthSamples).position;
    len += dist(q, prev);
    prev = q;
  }
  EXPECT_NEAR(len / path.length(), 0.5, 1e-4);
}

TEST(CurveCyclic, CyclicPathReturnsToItsStartAfterOneDuration) {
  for (CurveType type : kAllTypes)
    for (bool constantSpeed : {false, true}) {
      const PathSpec spec = makePath(type, true, constantSpeed);
      const Path path(spec);
      const glm::dvec3 start = path.atTime(0.0).position;
      // The end of the closed curve coincides with its start...
      EXPECT_LT(dist(evaluateCurve(spec, 1.0).position, start), 1e-9) << int(type);
      // ...and time wraps, so later laps repeat the first.
      EXPECT_LT(dist(path.atTime(spec.duration_s).position, start), 1e-9) << int(type);
      EXPECT_LT(dist(path.atTime(spec.duration_s * 2 + 1.3).position, path.atTime(1.3).position),
                1e-9);
    }
}

TEST(CurveCyclic, OpenPathStopsAtItsEnd) {
  const PathSpec spec = makePath(CurveType::BSpline3, false, true);
  const Path path(spec);
  EXPECT_LT(dist(path.atTime(spec.duration_s * 3).position, glm::dvec3(kUneven.back())), 1e-12);
}

TEST(CurveTime, FractionIsTimeOverDurationWrappedOrClamped) {
  PathSpec p = makePath(CurveType::Bezier, false);
  p.duration_s = 2.0f;
  EXPECT_DOUBLE_EQ(pathTimeFraction(p, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(pathTimeFraction(p, 5.0), 1.0);
  p.cyclic = true;
  EXPECT_DOUBLE_EQ(pathTimeFraction(p, 5.0), 0.5);
  EXPECT_DOUBLE_EQ(pathTimeFraction(p, 4.0), 0.0);
}

TEST(CurveDegenerate, SinglePointAndEmptyPathsAreFinite) {
  const PathSpec one = makePath(CurveType::BSpline3, false, true, {{1, 2, 3}});
  EXPECT_EQ(Path(one).atTime(1.0).position, glm::dvec3(1, 2, 3));
  const PathSpec two = makePath(CurveType::BSpline3, false, true, {{0, 0, 0}, {2, 0, 0}});
  EXPECT_LT(dist(Path(two).atTime(2.0).position, glm::dvec3(1, 0, 0)), 1e-9);  // degree drops to 1
  EXPECT_TRUE(Path(makePath(CurveType::CatmullRom, false, true, {})).empty());
}
