// Recorded tracks before resampling: poses on the recorder's own clock, as the CSV,
// JSON and glTF readers produce them. docs/tracks.md documents the file formats.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "api/loader_errors.h"  // TrackError

namespace taa::script {

// What a track drives: the allowed columns and keys differ (a lens for the camera,
// a scale or matrix for a mover).
enum class TrackSubject { Camera, Mover };

// Largest accepted | |q| - 1 |. Exporters print 6 to 9 digits, so honest unit
// quaternions miss by about 1e-6; a miss of 1e-3 means the four numbers are not an
// orientation (Euler angles, a column swapped, a forgotten normalisation).
inline constexpr double kUnitQuatTolerance = 1e-3;

// Largest accepted deviation of a basis from a rotation (|B^T B - I| per entry), and
// angle (radians) between a basis and the quaternion given beside it. Both come from
// the same double-precision pose when baked, so 1e-6 is generous.
inline constexpr double kBasisTolerance = 1e-6;

struct TrackSample {
  double time = 0.0;  // seconds on the track's clock
  std::string where;  // "file:line" or "file: camera.frames[3]", for messages
  glm::dvec3 position{0.0};
  glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // object (camera) to world, unit
  // The camera's rotation matrix when the track gives it (baked tracks do): replayed
  // as is on exact hits, because a quaternion cannot reproduce every bit of it (its
  // exact zeros come back as 1e-17). `orientation` then holds its quaternion.
  std::optional<glm::dmat3> basis;
  glm::dvec3 scale{1.0};            // movers only
  std::optional<glm::mat4> matrix;  // a mover given as a matrix: replayed as is on exact hits
  float fovYDeg = 0.0f;             // these three only where the track carries them
  float nearPlane = 0.0f;
  float farPlane = 0.0f;
  bool cut = false;  // a teleport: the new shot starts at this sample
};

struct RawTrack {
  std::string source;  // "file" or "file: movers[1]", for messages
  std::vector<TrackSample> samples;
  bool hasFov = false, hasNear = false, hasFar = false;
};

// Shortest decimal that reads back as `v`, for messages ("0.1", not "0.100000").
std::string trackNumber(double v);

// The rotation a track quaternion replays as, normalised in double.
glm::dmat3 orientationFromQuat(const glm::dquat& q);

// The rotation a sample replays as: its basis if it has one, else its quaternion's.
glm::dmat3 sampleOrientation(const TrackSample& s);

// Quaternion of a rotation matrix (columns: the object's x, y, z axes in world space).
glm::dquat quatFromOrientation(const glm::dmat3& m);

// Translation, rotation and scale of an affine matrix without shear (a negative
// determinant becomes a negative x scale), for interpolating matrix tracks.
void decomposeMatrix(const glm::mat4& m, TrackSample& out);

// Model matrix of a mover sample: the matrix if it has one, else T * R * S in double.
glm::mat4 sampleMatrix(const TrackSample& s);

// Rejects what cannot be replayed: no samples, NaN or Inf anywhere, quaternions
// further than kUnitQuatTolerance from unit length, a basis that is no rotation or
// disagrees with its quaternion, repeated or decreasing times, and lenses outside
// the case format's ranges. Throws TrackError naming the sample.
void checkTrack(const RawTrack& track);

}  // namespace taa::script
