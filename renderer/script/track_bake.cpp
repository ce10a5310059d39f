#include "script/track_bake.h"

#include <cstring>
#include <memory>
#include <stdexcept>

#include "script/frame_state.h"
#include "script/timing.h"
#include "script/tracks.h"

namespace taa::script {

namespace {

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

bool sameCamera(const CameraState& a, const CameraState& b) {
  return sameBits(a.position, b.position) && sameBits(a.view, b.view) &&
         sameBits(a.projection, b.projection) && sameBits(a.viewProjection, b.viewProjection) &&
         sameBits(a.fovY, b.fovY) && sameBits(a.nearPlane, b.nearPlane) &&
         sameBits(a.farPlane, b.farPlane);
}

bool sameFrame(const FrameState& a, const FrameState& b) {
  if (!sameCamera(a.camera, b.camera) || !sameCamera(a.prevCamera, b.prevCamera)) return false;
  if (a.cameraCut != b.cameraCut || a.resetHistory != b.resetHistory) return false;
  if (!sameBits(a.jitteredProjection, b.jitteredProjection)) return false;
  for (size_t i = 0; i < a.movers.size(); ++i)
    if (!sameBits(a.movers[i], b.movers[i]) || !sameBits(a.prevMovers[i], b.prevMovers[i]))
      return false;
  return true;
}

}  // namespace

TrackFile bakeTrack(const spec::CaseSpec& spec, const std::string& description) {
  TrackFile out;
  out.description = description;
  out.fps = spec.script.fps;
  RawTrack camera;
  camera.hasFov = camera.hasNear = camera.hasFar = true;
  out.movers.resize(spec.movers.size());
  for (int n = 0; n < spec.script.frames; ++n) {
    const CameraFrame f = cameraFrame(spec, n);
    TrackSample s;
    s.time = frameTime(spec.script, n);
    s.position = f.pose.position;
    s.basis = f.pose.orientation;  // exact; the quaternion beside it is for readers
    s.orientation = quatFromOrientation(f.pose.orientation);
    s.fovYDeg = f.fovYDeg;
    s.nearPlane = f.nearPlane;
    s.farPlane = f.farPlane;
    s.cut = f.cut;
    camera.samples.push_back(s);
    const FrameState fs = frameState(spec, n);
    for (size_t i = 0; i < spec.movers.size(); ++i) {
      TrackSample m;
      m.time = s.time;
      m.matrix = fs.movers[i];
      out.movers[i].samples.push_back(m);
    }
  }
  out.camera = std::move(camera);
  return out;
}

spec::CaseSpec replaySpec(const spec::CaseSpec& spec, const TrackFile& track) {
  spec::CaseSpec replay = spec;
  replay.camera = spec::CameraSpec{};
  replay.camera.track = "<baked>";
  auto tracks = std::make_shared<Tracks>();
  tracks->fps = spec.script.fps;
  tracks->frames = spec.script.frames;
  if (track.camera) {
    checkTrack(*track.camera);
    tracks->camera = cameraTrackFrames(*track.camera, replay);
  }
  tracks->movers.resize(spec.movers.size());
  for (size_t i = 0; i < spec.movers.size() && i < track.movers.size(); ++i) {
    const spec::MoverSpec& m = spec.movers[i];
    spec::MoverSpec& r = replay.movers[i];
    r = spec::MoverSpec{};
    r.shape = m.shape;
    r.gltf = m.gltf;
    r.color = m.color;
    r.animation_speed = m.animation_speed;
    r.track = "<baked>";
    checkTrack(track.movers[i]);
    tracks->movers[i] = moverTrackFrames(track.movers[i], replay, i);
  }
  replay.tracks = std::move(tracks);
  return replay;
}

std::string bakeTrackJson(const spec::CaseSpec& spec, const std::string& description) {
  const std::string text = writeJsonTrack(bakeTrack(spec, description));
  const spec::CaseSpec replay = replaySpec(spec, parseJsonTrack(text, "<baked track>"));
  for (int n = 0; n < spec.script.frames; ++n)
    if (!sameFrame(frameState(spec, n), frameState(replay, n)))
      throw std::logic_error("bake: replaying the baked track does not reproduce frame " +
                             std::to_string(n) + " bit for bit; please report this case");
  return text;
}

}  // namespace taa::script
