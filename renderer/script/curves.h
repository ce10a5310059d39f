// Camera fly-through paths (camera.path): Bezier, clamped/periodic uniform
// B-splines and uniform Catmull-Rom, with optional arc-length re-parameterisation.
// Everything is evaluated in double precision and depends only on the spec.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "spec/script_spec.h"

namespace taa::script {

struct CurvePoint {
  glm::dvec3 position{0.0};
  glm::dvec3 tangent{0.0};  // d position / d u (not normalised; may be zero at cusps)
};

// Number of chords in the arc-length table. Fixed so that every run and every
// frame inverts the same table; 4096 chords keep the speed error far below 0.1%.
inline constexpr int kArcLengthSamples = 4096;

// Evaluates the curve at its raw parameter u in [0,1] (clamped; no arc-length
// mapping). Segments are spread uniformly over u. An empty list yields the origin,
// one point yields that point with a zero tangent.
CurvePoint evaluateCurve(const spec::PathSpec& path, double u);

// Maps time to the path's normalised time: t / duration_s, wrapped to [0,1) when
// cyclic (so a cyclic path returns to its start), clamped to [0,1] otherwise.
double pathTimeFraction(const spec::PathSpec& path, double timeSeconds);

// A path with its arc-length table built once; cheap to query many times.
class Path {
 public:
  explicit Path(const spec::PathSpec& spec);

  bool empty() const { return spec_.points.empty(); }
  double length() const { return cumulative_.empty() ? 0.0 : cumulative_.back(); }

  // Raw parameter u at which the curve has covered `fraction` of its length.
  double parameterAtArcFraction(double fraction) const;

  // Raw parameter at time t (seconds): pathTimeFraction(), then, with
  // constant_speed, the arc-length inverse so equal time steps cover equal distances.
  double parameterAtTime(double timeSeconds) const;

  CurvePoint atTime(double timeSeconds) const;
  const spec::PathSpec& spec() const { return spec_; }

 private:
  spec::PathSpec spec_;
  std::vector<double> cumulative_;  // arc length at u = i / kArcLengthSamples
};

}  // namespace taa::script
