// Resampling to the case's fixed timestep: exact at the case's rate, linear position
// and fov with spherical-linear orientation otherwise, no blending across cuts.
#include "script/track_resample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/gtc/constants.hpp>

#include "script/track_csv.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

TrackSample at(double t, glm::dvec3 p, glm::dquat q = {1, 0, 0, 0}, bool cut = false) {
  TrackSample s;
  s.time = t;
  s.where = "t=" + std::to_string(t);
  s.position = p;
  s.orientation = q;
  s.cut = cut;
  return s;
}

double angleBetween(const glm::dquat& a, const glm::dquat& b) {
  return 2.0 * std::acos(std::min(1.0, std::fabs(glm::dot(glm::normalize(a), glm::normalize(b)))));
}

TEST(TrackResample, TrackAtTheCaseRateIsUsedAsIs) {
  RawTrack t;
  t.hasFov = true;
  for (int k = 0; k < 10; ++k) {
    // Awkward values: any arithmetic on them would change their bits.
    TrackSample s = at(k / 60.0, {std::sqrt(2.0) * k, 1.0 / 3.0, -std::cbrt(7.0 + k)},
                       glm::normalize(glm::dquat(0.3, 0.1 * k, 0.7, std::sqrt(0.2))));
    s.fovYDeg = 50.0f + float(k) / 7.0f;
    t.samples.push_back(s);
  }
  const auto r = resampleTrack(t, 0.0, 60, 10);
  for (int k = 0; k < 10; ++k) {
    EXPECT_EQ(std::memcmp(&r[k].position, &t.samples[k].position, sizeof(glm::dvec3)), 0) << k;
    EXPECT_EQ(std::memcmp(&r[k].orientation, &t.samples[k].orientation, sizeof(glm::dquat)), 0);
    EXPECT_EQ(r[k].fovYDeg, t.samples[k].fovYDeg);
  }
  // Half the case's rate hits every other sample exactly too.
  const auto half = resampleTrack(t, 0.0, 30, 5);
  EXPECT_EQ(half[3].position, t.samples[6].position);
}

// The analytic motion recorded at 144 Hz and replayed at 60 Hz (2.4 samples per frame,
// so almost every frame is interpolated): position p(t) = (2 sin(pi t), 0.5 cos(pi t),
// 3 t), a constant-rate turn of 1.3 rad/s about a fixed axis, fov 60 - 10 t degrees.
glm::dvec3 analyticPosition(double t) {
  const double pi = glm::pi<double>();
  return {2.0 * std::sin(pi * t), 0.5 * std::cos(pi * t), 3.0 * t};
}
glm::dquat analyticOrientation(double t) {
  return glm::angleAxis(1.3 * t, glm::normalize(glm::dvec3(1.0, 2.0, 3.0)));
}

TEST(TrackResample, Recording144HzReplayedAt60HzMatchesTheAnalyticMotion) {
  // Written as an engine would: a frame-numbered CSV with 9 significant digits.
  std::string csv = "# fps: 144\nframe,px,py,pz,qx,qy,qz,qw,fov_y_deg\n";
  for (int k = 0; k <= 2 * 144; ++k) {
    const double t = k / 144.0;
    const glm::dvec3 p = analyticPosition(t);
    const glm::dquat q = analyticOrientation(t);
    char row[256];
    std::snprintf(row, sizeof(row), "%d,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n", k, p.x, p.y,
                  p.z, q.x, q.y, q.z, q.w, 60.0 - 10.0 * t);
    csv += row;
  }
  const RawTrack track = parseCsvTrack(csv, "144hz.csv", TrackSubject::Camera);
  checkTrack(track);
  const auto r = resampleTrack(track, 0.0, 60, 120);
  // Linear interpolation of a C2 curve errs by at most h^2 / 8 * max|p''| with
  // h = 1/144 s; |p''| <= pi^2 * sqrt(4 + 0.25), so the bound is 1.23e-4 units.
  const double h = 1.0 / 144.0;
  const double positionTolerance =
      h * h / 8.0 * glm::pi<double>() * glm::pi<double>() * std::sqrt(4.25) + 1e-8;
  EXPECT_LT(positionTolerance, 1.25e-4);
  double worstPosition = 0.0, worstAngle = 0.0, worstFov = 0.0;
  for (int n = 0; n < 120; ++n) {
    const double t = n / 60.0;
    worstPosition = std::max(worstPosition, glm::length(r[n].position - analyticPosition(t)));
    worstAngle = std::max(worstAngle, angleBetween(r[n].orientation, analyticOrientation(t)));
    worstFov = std::max(worstFov, std::fabs(double(r[n].fovYDeg) - (60.0 - 10.0 * t)));
  }
  EXPECT_LT(worstPosition, positionTolerance);
  EXPECT_GT(worstPosition, 1e-6);  // it did interpolate: the bound is not vacuous
  // Slerp follows a constant-rate turn about a fixed axis exactly; what is left is
  // the 9 printed digits.
  EXPECT_LT(worstAngle, 1e-7);
  // The fov is linear in time, so only float rounding remains.
  EXPECT_LT(worstFov, 1e-5);
}

TEST(TrackResample, SlerpTakesTheShorterArc) {
  RawTrack t;
  const glm::dquat a = glm::angleAxis(0.1, glm::dvec3(0, 1, 0));
  const glm::dquat b = -glm::angleAxis(0.3, glm::dvec3(0, 1, 0));  // same as +, sign flipped
  t.samples = {at(0.0, {}, a), at(1.0, {}, b)};
  const auto r = resampleTrack(t, 0.0, 2, 2);
  EXPECT_LT(angleBetween(r[1].orientation, glm::angleAxis(0.2, glm::dvec3(0, 1, 0))), 1e-12);
}

TEST(TrackResample, CutsAreNotBlendedAcrossAndFlagTheFirstFrameAfterThem) {
  RawTrack t;
  t.samples = {at(0.0, {0, 0, 0}), at(0.1, {100, 0, 0}, {1, 0, 0, 0}, true), at(0.2, {110, 0, 0})};
  const auto r = resampleTrack(t, 0.0, 35, 7);  // frames at 0, 0.029, 0.057, 0.086, 0.114, ...
  for (int n = 0; n < 4; ++n) {
    EXPECT_EQ(r[n].position, glm::dvec3(0.0)) << "frame " << n << " must hold the old shot";
    EXPECT_FALSE(r[n].cut) << n;
  }
  EXPECT_TRUE(r[4].cut);
  EXPECT_NEAR(r[4].position.x, 100.0 + 10.0 * (4.0 / 35.0 - 0.1) / 0.1, 1e-9);
  EXPECT_FALSE(r[5].cut);
}

TEST(TrackResample, TimeOffsetShiftsTheTrack) {
  RawTrack t;
  t.samples = {at(0.0, {0, 0, 0}), at(10.0, {10, 0, 0})};
  const auto r = resampleTrack(t, 2.5, 4, 3);
  EXPECT_DOUBLE_EQ(r[0].position.x, 2.5);
  EXPECT_DOUBLE_EQ(r[2].position.x, 3.0);
}

TEST(TrackResample, TimesOutsideTheTrackAreErrorsNotClamps) {
  RawTrack t;
  t.source = "short.csv";
  t.samples = {at(0.0, {}), at(0.05, {})};
  const std::string e = test::errorOf<TrackError>([&] { resampleTrack(t, 0.0, 60, 10); });
  EXPECT_TRUE(test::contains(e, "short.csv: frame 4 replays t = 0.0666"));
}

}  // namespace
}  // namespace taa::script
