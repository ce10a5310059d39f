#include "script/movers.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "script/timing.h"

namespace taa::script {

double repeatedOffset(spec::Repeat repeat, double travelled, double length) {
  if (!(length > 0.0)) return 0.0;
  switch (repeat) {
    case spec::Repeat::Once:
      return std::clamp(travelled, 0.0, length);
    case spec::Repeat::Cyclic: {
      const double s = std::fmod(travelled, length);
      return s < 0.0 ? s + length : s;
    }
    case spec::Repeat::PingPong: {
      double s = std::fmod(travelled, 2.0 * length);
      if (s < 0.0) s += 2.0 * length;
      return s <= length ? s : 2.0 * length - s;
    }
  }
  return 0.0;
}

MoverState moverState(const spec::MoverSpec& mover, const spec::TimingSpec& timing, int frame) {
  MoverState st;
  const double t = frameTime(timing, frame);
  const double speed = mover.speed;
  st.travelled = mover.speed_unit == spec::SpeedUnit::PerFrame ? speed * frame : speed * t;

  const glm::dvec3 start(mover.start), end(mover.end);
  const double length = glm::length(end - start);
  st.offset = repeatedOffset(mover.repeat, st.travelled, length);
  st.position = length > 0.0 ? start + (end - start) / length * st.offset : start;

  const double rate = mover.rotation_speed_deg;
  // Reduced in double before the float matrix sees it: angles grow without bound.
  st.angleDeg = std::fmod(mover.continuous_rotation ? rate * t : rate * st.offset, 360.0);
  st.animationTime =
      double(mover.animation_offset_s) + t * static_cast<double>(mover.animation_speed);

  glm::dmat4 model = glm::translate(glm::dmat4(1.0), st.position);
  const glm::dvec3 axis(mover.rotation_axis);
  if (glm::length(axis) > 0.0)
    model = glm::rotate(model, glm::radians(st.angleDeg), glm::normalize(axis));
  model = glm::scale(model, glm::dvec3(static_cast<double>(mover.size)));
  st.model = glm::mat4(model);
  return st;
}

}  // namespace taa::script
