#include "script/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include "script/timing.h"

namespace taa::script {

namespace {

// Below this a direction counts as zero: far under any meaningful scene scale,
// far above the rounding noise of double arithmetic.
constexpr double kTiny = 1e-12;

glm::dmat3 rotationY(double degrees) {
  // Reduce first: yaw grows without bound and sin/cos of huge angles lose digits.
  const double a = glm::radians(std::fmod(degrees, 360.0));
  const double c = std::cos(a), s = std::sin(a);
  return glm::dmat3(glm::dvec3(c, 0, -s), glm::dvec3(0, 1, 0), glm::dvec3(s, 0, c));
}

glm::dmat3 rotationX(double degrees) {
  const double a = glm::radians(degrees);
  const double c = std::cos(a), s = std::sin(a);
  return glm::dmat3(glm::dvec3(1, 0, 0), glm::dvec3(0, c, s), glm::dvec3(0, -s, c));
}

// Direction of travel at raw parameter u; at a cusp (zero derivative, e.g. repeated
// control points) the chord to a nearby point stands in for it.
glm::dvec3 travelDirection(const Path& path, double u) {
  const CurvePoint here = evaluateCurve(path.spec(), u);
  if (glm::length(here.tangent) > kTiny) return here.tangent;
  constexpr double h = 1e-4;
  const double a = std::max(0.0, u - h), b = std::min(1.0, u + h);
  return evaluateCurve(path.spec(), b).position - evaluateCurve(path.spec(), a).position;
}

}  // namespace

glm::mat4 CameraPose::view() const {
  const glm::dmat3 worldToCamera = glm::transpose(orientation);
  glm::dmat4 v(worldToCamera);
  v[3] = glm::dvec4(-(worldToCamera * position), 1.0);
  return glm::mat4(v);
}

glm::dmat3 lookOrientation(const glm::dvec3& forward) {
  const double len = glm::length(forward);
  const glm::dvec3 f = len > kTiny ? forward / len : glm::dvec3(0, 0, -1);
  glm::dvec3 upHint(0, 1, 0);
  if (std::hypot(f.x, f.z) <= 1e-9) upHint = glm::dvec3(0, 0, f.y < 0.0 ? -1.0 : 1.0);
  const glm::dvec3 right = glm::normalize(glm::cross(f, upHint));
  const glm::dvec3 up = glm::cross(right, f);
  return glm::dmat3(right, up, -f);
}

int activeCut(const spec::CameraSpec& camera, int frame) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(camera.cuts.size()); ++i) {
    const int f = camera.cuts[i].frame;
    if (f <= frame && (best < 0 || f >= camera.cuts[best].frame)) best = i;
  }
  return best;
}

bool cutStartsAt(const spec::CameraSpec& camera, int frame) {
  for (const auto& cut : camera.cuts)
    if (cut.frame == frame) return true;
  return false;
}

double pitchDegrees(double rateDegPerS, double timeSeconds) {
  constexpr double kLimit = 30.0;
  // Phase 0 is the bottom of the wave, so the travelled angle starts at +kLimit.
  const double period = 4.0 * kLimit;
  double phase = std::fmod(rateDegPerS * timeSeconds + kLimit, period);
  if (phase < 0.0) phase += period;
  return phase <= 2.0 * kLimit ? phase - kLimit : 3.0 * kLimit - phase;
}

double bobOffset(const spec::BobSpec& bob, double timeSeconds) {
  const double cycles = std::fmod(static_cast<double>(bob.frequency_hz) * timeSeconds, 1.0);
  return bob.amplitude * std::sin(2.0 * glm::pi<double>() * cycles);
}

double strafeOffset(const spec::StrafeSpec& strafe, double timeSeconds) {
  const double x = static_cast<double>(strafe.speed) * timeSeconds;
  const double d = strafe.distance;
  if (!(d > 0.0)) return x;
  const double phase = std::fmod(x + d, 4.0 * d);  // x >= 0: speed is never negative
  return phase <= 2.0 * d ? phase - d : 3.0 * d - phase;
}

CameraPose cameraPose(const spec::CameraSpec& camera, const Path& path, int frame,
                      double timeSeconds) {
  glm::dvec3 basePos(camera.position), baseTarget(camera.target);
  if (const int cut = activeCut(camera, frame); cut >= 0) {
    basePos = glm::dvec3(camera.cuts[cut].position);
    baseTarget = glm::dvec3(camera.cuts[cut].target);
  }
  const glm::dmat3 baseOrientation = lookOrientation(baseTarget - basePos);

  CameraPose pose{basePos, baseOrientation};
  if (!path.empty()) {
    const double u = path.parameterAtTime(timeSeconds);
    pose.position = evaluateCurve(path.spec(), u).position;
    switch (path.spec().look) {
      case spec::LookMode::Along:
        pose.orientation = lookOrientation(travelDirection(path, u));
        break;
      case spec::LookMode::Target: {
        const glm::dvec3 toTarget = baseTarget - pose.position;
        if (glm::length(toTarget) > kTiny) pose.orientation = lookOrientation(toTarget);
        break;
      }
      case spec::LookMode::Fixed:
        break;
    }
  }

  // Yaw about world up, pitch about the camera's own right axis: carrying the full
  // rotation (not a look-at) keeps the pose defined even when pitched vertical.
  pose.orientation = rotationY(double(camera.rotate.yaw_deg_per_s) * timeSeconds) *
                     pose.orientation *
                     rotationX(pitchDegrees(camera.rotate.pitch_deg_per_s, timeSeconds));
  pose.position.y += bobOffset(camera.bob, timeSeconds);
  pose.position += strafeOffset(camera.strafe, timeSeconds) * pose.right();
  return pose;
}

CameraPose cameraPose(const spec::CameraSpec& camera, const spec::TimingSpec& timing, int frame) {
  return cameraPose(camera, Path(camera.path), frame, frameTime(timing, frame));
}

}  // namespace taa::script
