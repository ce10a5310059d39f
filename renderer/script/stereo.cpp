#include "script/stereo.h"

#include <glm/gtc/matrix_transform.hpp>

#include "spec/taa_modes.h"

namespace taa {

namespace {

// Moving the camera by d along its own right axis moves the world by -d in view space.
void shift(script::CameraState& c, float d) {
  const glm::vec3 right(c.view[0][0], c.view[1][0], c.view[2][0]);
  c.position += right * d;
  c.view = glm::translate(glm::mat4(1.0f), glm::vec3(-d, 0.0f, 0.0f)) * c.view;
  c.viewProjection = c.projection * c.view;
}

}  // namespace

int eyeCount(const spec::CaseSpec& spec) {
  return spec::modeRule(spec.taa.mode).tscmaa ? spec.tscmaa.eyes : 1;
}

glm::ivec2 outputSize(const spec::CaseSpec& spec) {
  return {spec.render.width * eyeCount(spec), spec.render.height};
}

script::FrameState eyeFrameState(const script::FrameState& frame, int eye, int eyes,
                                 float separation) {
  if (eyes < 2) return frame;
  script::FrameState s = frame;
  const float d = (eye == 0 ? -0.5f : 0.5f) * separation;
  shift(s.camera, d);
  shift(s.prevCamera, d);
  return s;
}

}  // namespace taa
