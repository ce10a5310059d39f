// Moving objects (movers[]): straight-line motion between start and end with
// once / cyclic / ping-pong repeat, plus rotation and glTF animation time.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "spec/script_spec.h"

namespace taa::script {

struct MoverState {
  double travelled = 0.0;      // s: distance covered since frame 0 (speed * t or speed * frame)
  double offset = 0.0;         // s': distance from start after repeat, in [0, |end - start|]
  glm::dvec3 position{0.0};    // start + dir * s'
  double angleDeg = 0.0;       // about the normalised rotation_axis, reduced to (-360, 360)
  double animationTime = 0.0;  // seconds into the glTF animations: offset + t * animation_speed
  glm::mat4 model{1.0f};       // translate(position) * rotate(angle, axis) * scale(size)
};

// Distance from start after applying `repeat` to a travelled distance s >= 0 on a
// segment of length L: once clamps to [0, L]; cyclic wraps (s mod L), jumping back
// to start; ping_pong is a triangle wave of period 2L. L = 0 gives 0.
double repeatedOffset(spec::Repeat repeat, double travelled, double length);

// State at `frame` with t = frame / fps. Rotation: continuous_rotation gives
// rotation_speed_deg * t; otherwise rotation_speed_deg * s' (degrees per unit of
// position along the line, so a rolling object turns back on the way back).
// A zero rotation axis means no rotation.
MoverState moverState(const spec::MoverSpec& mover, const spec::TimingSpec& timing, int frame);

}  // namespace taa::script
