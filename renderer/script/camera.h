// Camera pose per frame (camera.*): base pose, cuts, fly-through path and the
// procedural rotation, bobbing and strafing, applied in that order.
// World: right-handed, +Y up; the camera looks down -Z of its view space.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "script/curves.h"
#include "spec/script_spec.h"

namespace taa::script {

struct CameraPose {
  glm::dvec3 position{0.0};
  // Camera-to-world rotation; columns are the camera's right, up and back (+Z)
  // axes, so the view direction is -orientation[2].
  glm::dmat3 orientation{1.0};

  glm::dvec3 right() const { return orientation[0]; }
  glm::dvec3 up() const { return orientation[1]; }
  glm::dvec3 forward() const { return -orientation[2]; }
  glm::mat4 view() const;  // world -> view, the inverse of [orientation | position]
};

// A pose with its lens and cut flag: what the script or a recorded track gives per
// frame, and what a baked track stores.
struct CameraFrame {
  CameraPose pose;
  float fovYDeg = 60.0f;
  float nearPlane = 0.1f, farPlane = 1000.0f;
  bool cut = false;  // a new shot starts at this frame
};

// Orientation facing `forward` with world +Y as the up hint, as glm::lookAt does.
// Looking straight up or down has no such up; the hint then becomes -Z when looking
// down and +Z when looking up, i.e. the screen's top keeps pointing where a camera
// tilted from the default -Z view would point. A zero direction faces -Z.
glm::dmat3 lookOrientation(const glm::dvec3& forward);

// Index of the cut in force at `frame`: the one with the greatest frame <= frame
// (the later listed on ties), or -1 before the first cut.
int activeCut(const spec::CameraSpec& camera, int frame);

// True when some cut starts exactly at `frame`.
bool cutStartsAt(const spec::CameraSpec& camera, int frame);

// Pitch in degrees: a triangle wave starting at 0, moving at |rate| deg/s (upwards
// for a positive rate) and reversing at +-30 degrees.
double pitchDegrees(double rateDegPerS, double timeSeconds);

// Vertical bob: amplitude * sin(2 pi f t).
double bobOffset(const spec::BobSpec& bob, double timeSeconds);

// Sideways offset along the camera's right axis: a triangle wave 0 -> +d -> -d -> 0
// at `speed`, or speed * t without turning back when distance is 0.
double strafeOffset(const spec::StrafeSpec& strafe, double timeSeconds);

// The pose at `frame` (time = frame / fps). `path` must be built from camera.path;
// passing it lets callers evaluating several frames build the arc-length table once.
CameraPose cameraPose(const spec::CameraSpec& camera, const Path& path, int frame,
                      double timeSeconds);
CameraPose cameraPose(const spec::CameraSpec& camera, const spec::TimingSpec& timing, int frame);

}  // namespace taa::script
