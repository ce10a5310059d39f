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
#include "script/tracks.h"

namespace taa::script {

namespace {

CameraState toCameraState(const spec::CaseSpec& spec, const CameraFrame& frame) {
  CameraState cam;
  cam.position = glm::vec3(frame.pose.position);
  cam.view = frame.pose.view();
  cam.fovY = glm::radians(frame.fovYDeg);
  cam.aspect = static_cast<float>(spec.render.width) / static_cast<float>(spec.render.height);
  cam.nearPlane = frame.nearPlane;
  cam.farPlane = frame.farPlane;
  cam.projection = reversedZPerspective(cam.fovY, cam.aspect, cam.nearPlane, cam.farPlane);
  cam.viewProjection = cam.projection * cam.view;
  return cam;
}

// The loaded tracks when the case replays any, checked against the frame asked for.
const Tracks* tracksFor(const spec::CaseSpec& spec, int frame) {
  if (!usesTracks(spec)) return nullptr;
  const Tracks* t = spec.tracks.get();
  if (!t || t->fps != spec.script.fps || t->frames != spec.script.frames)
    throw std::logic_error("frameState: " + spec.file.string() +
                           " replays tracks that were not loaded for its script.fps and "
                           "script.frames; load the case with cases::loadCase / parseCase, or "
                           "set spec.tracks from script::loadTracks(spec) after editing it");
  if (frame >= t->frames)
    throw std::out_of_range("frameState: frame " + std::to_string(frame) +
                            " is past the recorded tracks' " + std::to_string(t->frames) +
                            " frames");
  return t;
}

CameraFrame cameraFrameAt(const spec::CaseSpec& spec, const Tracks* tracks, const Path& path,
                          int frame) {
  if (tracks && !tracks->camera.empty()) return tracks->camera[size_t(frame)];
  CameraFrame f;
  f.pose = cameraPose(spec.camera, path, frame, frameTime(spec.script, frame));
  f.fovYDeg = spec.camera.fov_y_deg;
  f.nearPlane = spec.camera.near_plane;
  f.farPlane = spec.camera.far_plane;
  f.cut = cutStartsAt(spec.camera, frame);
  return f;
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

CameraFrame cameraFrame(const spec::CaseSpec& spec, int frame) {
  if (frame < 0) throw std::out_of_range("cameraFrame: negative frame " + std::to_string(frame));
  return cameraFrameAt(spec, tracksFor(spec, frame), Path(spec.camera.path), frame);
}

FrameState frameState(const spec::CaseSpec& spec, int frame) {
  if (frame < 0) throw std::out_of_range("frameState: negative frame " + std::to_string(frame));
  const Tracks* tracks = tracksFor(spec, frame);
  FrameState fs;
  fs.frame = frame;
  fs.time = frameTime(spec.script, frame);
  fs.renderScale = renderScaleAt(spec.render, frame);
  fs.renderSize = renderSizeFor(spec.render, fs.renderScale);

  const Path path(spec.camera.path);
  const CameraFrame current = cameraFrameAt(spec, tracks, path, frame);
  fs.cameraCut = current.cut;
  fs.camera = toCameraState(spec, current);
  // A cut is a new shot: there is no meaningful previous view to reproject from.
  const bool samePrev = frame == 0 || fs.cameraCut;
  fs.prevCamera =
      samePrev ? fs.camera : toCameraState(spec, cameraFrameAt(spec, tracks, path, frame - 1));

  fs.jitter = jitterOffset(spec.jitter, frame);
  fs.jitteredProjection = applyJitter(fs.camera.projection, fs.jitter, fs.renderSize);

  // Movers keep moving through a camera cut, so their previous transform is always
  // frame - 1 (only frame 0 has none).
  const int prevFrame = std::max(0, frame - 1);
  for (size_t i = 0; i < spec.movers.size(); ++i) {
    const MoverState now = moverState(spec.movers[i], spec.script, frame);
    const MoverState before = moverState(spec.movers[i], spec.script, prevFrame);
    const bool recorded = tracks && !tracks->movers[i].empty();
    fs.movers.push_back(recorded ? tracks->movers[i][size_t(frame)] : now.model);
    fs.prevMovers.push_back(recorded ? tracks->movers[i][size_t(prevFrame)] : before.model);
    // A recorded mover's glTF animation still runs on the case's clock.
    fs.moverAnimTime.push_back(now.animationTime);
    fs.prevMoverAnimTime.push_back(before.animationTime);
  }

  auto worldAnim = [&](int f) {
    return double(spec.scene.animation_offset_s) +
           double(spec.scene.animation_speed) * frameTime(spec.script, f);
  };
  fs.worldAnimTime = worldAnim(frame);
  fs.prevWorldAnimTime = worldAnim(prevFrame);

  const auto& resets = spec.script.reset_history_at;
  fs.resetHistory =
      frame == 0 || fs.cameraCut || std::find(resets.begin(), resets.end(), frame) != resets.end();
  return fs;
}

}  // namespace taa::script
