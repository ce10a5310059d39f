#include "script/track.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>

namespace taa::script {

namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

[[noreturn]] void fail(const TrackSample& s, const std::string& what) {
  throw TrackError(s.where + ": " + what);
}

void checkLens(const RawTrack& t, const TrackSample& s) {
  if (t.hasFov && !(s.fovYDeg >= 1.0f && s.fovYDeg <= 179.0f))
    fail(s, "fov_y_deg " + trackNumber(s.fovYDeg) +
                " is outside [1, 179]; give the vertical field "
                "of view in degrees");
  if (t.hasNear && !(s.nearPlane > 0.0f && std::isfinite(s.nearPlane)))
    fail(s, "near " + trackNumber(s.nearPlane) + " must be a positive distance");
  if (t.hasFar && !(s.farPlane > 0.0f && std::isfinite(s.farPlane)))
    fail(s, "far " + trackNumber(s.farPlane) + " must be a positive distance");
  if (t.hasNear && t.hasFar && !(s.nearPlane < s.farPlane))
    fail(s, "near " + trackNumber(s.nearPlane) + " is not below far " + trackNumber(s.farPlane));
}

void checkBasis(const TrackSample& s) {
  const glm::dmat3& b = *s.basis;
  for (int c = 0; c < 3; ++c)
    if (!finite(b[c])) fail(s, "the basis has a NaN or infinite entry; fix the exporter");
  const glm::dmat3 gram = glm::transpose(b) * b;
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
    for (int r = 0; r < 3; ++r)
      worst = std::max(worst, std::fabs(gram[c][r] - (c == r ? 1.0 : 0.0)));
  if (worst > kBasisTolerance || glm::determinant(b) < 0.0)
    fail(s,
         "the basis is not a rotation (orthonormal columns right, up, back with determinant "
         "+1); give a rotation matrix or only the orientation quaternion");
  const double dot = std::fabs(glm::dot(glm::normalize(s.orientation), quatFromOrientation(b)));
  if (2.0 * std::acos(std::min(1.0, dot)) > kBasisTolerance)
    fail(s,
         "the basis and the orientation quaternion disagree; give one of them, or both from "
         "the same pose");
}

}  // namespace

std::string trackNumber(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

glm::dmat3 orientationFromQuat(const glm::dquat& q) {
  return glm::mat3_cast(glm::normalize(q));
}

glm::dmat3 sampleOrientation(const TrackSample& s) {
  return s.basis ? *s.basis : orientationFromQuat(s.orientation);
}

glm::dquat quatFromOrientation(const glm::dmat3& m) {
  return glm::normalize(glm::quat_cast(m));
}

void decomposeMatrix(const glm::mat4& m, TrackSample& out) {
  const glm::dmat4 d(m);
  out.position = glm::dvec3(d[3]);
  glm::dmat3 basis(d);
  glm::dvec3 s(glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2]));
  if (glm::determinant(basis) < 0.0) s.x = -s.x;
  out.scale = s;
  if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0) {
    out.orientation = glm::dquat(1.0, 0.0, 0.0, 0.0);  // a collapsed axis has no rotation
    return;
  }
  for (int i = 0; i < 3; ++i) basis[i] /= s[i];
  out.orientation = quatFromOrientation(basis);
}

glm::mat4 sampleMatrix(const TrackSample& s) {
  if (s.matrix) return *s.matrix;
  glm::dmat4 model = glm::translate(glm::dmat4(1.0), s.position);
  model = model * glm::dmat4(orientationFromQuat(s.orientation));
  return glm::mat4(glm::scale(model, s.scale));
}

void checkTrack(const RawTrack& track) {
  if (track.samples.empty())
    throw TrackError(track.source +
                     ": the track has no samples; record at least the frames "
                     "the case replays");
  for (size_t i = 0; i < track.samples.size(); ++i) {
    const TrackSample& s = track.samples[i];
    if (!std::isfinite(s.time)) fail(s, "the timestamp is not a finite number");
    if (!finite(s.position)) fail(s, "the position is NaN or infinite; fix the exporter");
    const glm::dvec4 q(s.orientation.x, s.orientation.y, s.orientation.z, s.orientation.w);
    if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z) && std::isfinite(q.w)))
      fail(s, "the orientation quaternion is NaN or infinite; fix the exporter");
    if (!finite(s.scale)) fail(s, "the scale is NaN or infinite; fix the exporter");
    if (s.matrix)
      for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
          if (!std::isfinite((*s.matrix)[c][r])) fail(s, "the matrix has a NaN or infinite entry");
    const double len = glm::length(q);
    if (std::fabs(len - 1.0) > kUnitQuatTolerance)
      fail(s, "the orientation quaternion (x, y, z, w) has length " + trackNumber(len) +
                  ", not 1 within " + trackNumber(kUnitQuatTolerance) +
                  "; write unit quaternions (normalise them in the exporter, and check the "
                  "column order x, y, z, w)");
    if (s.basis) checkBasis(s);
    checkLens(track, s);
    if (i == 0) continue;
    const TrackSample& prev = track.samples[i - 1];
    if (s.time == prev.time)
      fail(s, "timestamp " + trackNumber(s.time) + " s repeats the one at " + prev.where +
                  "; remove the duplicate sample");
    if (s.time < prev.time)
      fail(s, "timestamp " + trackNumber(s.time) + " s comes before " + trackNumber(prev.time) +
                  " s at " + prev.where + "; samples must be in increasing time order");
  }
}

}  // namespace taa::script
