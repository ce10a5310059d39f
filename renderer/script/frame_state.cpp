#include "script/frame_state.h"

#include <algorithm>
#include <cmath>
#include <glm/trigonometric.hpp>
#include <stdexcept>
#include <string>

#include "script/camera.h"
#include "script/curves.h"
#include "script/jitter.h"
#include "script/movers.h"
#include "script/projection.h"
#include "script/timing.h"

namespace taa::script {

namespace {

CameraState toCameraState(const spec::CaseSpec& spec, const CameraPose& pose) {
  CameraState cam;
  cam.position = glm::vec3(pose.position);
  cam.view = pose.view();
  cam.fovY = glm::radians(spec.camera.fov_y_deg);
  cam.aspect = static_cast<float>(spec.render.width) / static_cast<float>(spec.render.height);
  cam.nearPlane = spec.camera.near_plane;
  cam.farPlane = spec.camera.far_plane;
  cam.projection = reversedZPerspective(cam.fovY, cam.aspect, cam.nearPlane, cam.farPlane);
  cam.viewProjection = cam.projection * cam.view;
  return cam;
}

}  // namespace

float renderScaleAt(const spec::RenderSpec& render, int frame) {
  int best = -1;
  for (int i = 0; i < static_cast<int>(render.scale_schedule.size()); ++i) {
    const int f = render.scale_schedule[i].frame;
    if (f <= frame && (best < 0 || f >= render.scale_schedule[best].frame)) best = i;
  }
  return best < 0 ? 1.0f : render.scale_schedule[best].scale;
}

glm::ivec2 renderSizeFor(const spec::RenderSpec& render, float scale) {
  auto axis = [&](int output) {
    const long full = std::lround(static_cast<float>(output) / render.upsample);
    return static_cast<int>(std::max(1L, std::lround(static_cast<float>(full) * scale)));
  };
  return {axis(render.width), axis(render.height)};
}

CameraState cameraState(const spec::CaseSpec& spec, int frame) {
  return toCameraState(spec, cameraPose(spec.camera, spec.script, frame));
}

FrameState frameState(const spec::CaseSpec& spec, int frame) {
  if (frame < 0) throw std::out_of_range("frameState: negative frame " + std::to_string(frame));
  FrameState fs;
  fs.frame = frame;
  fs.time = frameTime(spec.script, frame);
  fs.renderScale = renderScaleAt(spec.render, frame);
  fs.renderSize = renderSizeFor(spec.render, fs.renderScale);

  const Path path(spec.camera.path);
  fs.cameraCut = cutStartsAt(spec.camera, frame);
  fs.camera = toCameraState(spec, cameraPose(spec.camera, path, frame, fs.time));
  // A cut is a new shot: there is no meaningful previous view to reproject from.
  const bool samePrev = frame == 0 || fs.cameraCut;
  fs.prevCamera = samePrev ? fs.camera
                           : toCameraState(spec, cameraPose(spec.camera, path, frame - 1,
                                                            frameTime(spec.script, frame - 1)));

  fs.jitter = jitterOffset(spec.jitter, frame);
  fs.jitteredProjection = applyJitter(fs.camera.projection, fs.jitter, fs.renderSize);

  // Movers keep moving through a camera cut, so their previous transform is always
  // frame - 1 (only frame 0 has none).
  const int prevFrame = std::max(0, frame - 1);
  for (const auto& mover : spec.movers) {
    const MoverState now = moverState(mover, spec.script, frame);
    const MoverState before = moverState(mover, spec.script, prevFrame);
    fs.movers.push_back(now.model);
    fs.prevMovers.push_back(before.model);
    fs.moverAnimTime.push_back(now.animationTime);
    fs.prevMoverAnimTime.push_back(before.animationTime);
  }

  const auto& resets = spec.script.reset_history_at;
  fs.resetHistory =
      frame == 0 || fs.cameraCut || std::find(resets.begin(), resets.end(), frame) != resets.end();
  return fs;
}

}  // namespace taa::script
