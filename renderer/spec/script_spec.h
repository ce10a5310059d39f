// The replayed script: timing, camera, movers and jitter. Everything here is
// evaluated as a pure function of the frame index (renderer/script/).
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "spec/fields.h"

namespace taa::spec {

struct TimingSpec {
  int fps = 60;
  int frames = 16;
  std::vector<int> reset_history_at;
};

template <class V>
void fields(V& v, TimingSpec& s) {
  v.field("fps", s.fps, Range<int>{1, 1000},
          Meta{"fixed timestep: frame n is at time n / fps seconds", "renderer/script/frame_state.cpp"});
  v.field("frames", s.frames, Range<int>{1, 100000}, Meta{"number of frames replayed", "renderer/script/frame_state.cpp"});
  v.field("reset_history_at", s.reset_history_at, Range<int>{0, 99999},
          Meta{"frames at which the TAA history is discarded", "renderer/passes/taa_resolve.cpp"});
}

enum class CurveType { Bezier, BSpline2, BSpline3, CatmullRom };
TAA_ENUM_NAMES(CurveType, {CurveType::Bezier, "bezier"}, {CurveType::BSpline2, "bspline2"},
               {CurveType::BSpline3, "bspline3"}, {CurveType::CatmullRom, "catmull_rom"})

enum class LookMode { Along, Target, Fixed };
TAA_ENUM_NAMES(LookMode, {LookMode::Along, "along"}, {LookMode::Target, "target"}, {LookMode::Fixed, "fixed"})

struct PathSpec {
  CurveType type = CurveType::CatmullRom;
  std::vector<glm::vec3> points;  // empty: no path
  float duration_s = 4.0f;
  bool constant_speed = true;
  LookMode look = LookMode::Along;
  bool cyclic = false;
};

template <class V>
void fields(V& v, PathSpec& s) {
  const char* impl = "renderer/script/curves.cpp";
  v.field("type", s.type, Meta{"interpolation of the control points", impl});
  v.field("points", s.points, Meta{"control points; an empty list means no path", impl});
  v.field("duration_s", s.duration_s, Range<float>{1e-3f, 1e6f}, Meta{"time to traverse the path once", impl});
  v.field("constant_speed", s.constant_speed,
          Meta{"re-parameterise by arc length so the camera moves at constant speed", impl});
  v.field("look", s.look,
          Meta{"along: face the path tangent; target: face the target in force (camera.target or "
               "the latest cut's); fixed: keep the orientation of that base pose",
               "renderer/script/camera.cpp"});
  v.field("cyclic", s.cyclic, Meta{"close the path and loop; otherwise stop at the end", impl});
}

struct RotateSpec {
  float yaw_deg_per_s = 0.0f;
  float pitch_deg_per_s = 0.0f;
};

template <class V>
void fields(V& v, RotateSpec& s) {
  const char* impl = "renderer/script/camera.cpp";
  v.field("yaw_deg_per_s", s.yaw_deg_per_s, Range<float>{-1e5f, 1e5f},
          Meta{"rotation about the world up axis; positive turns left (counter-clockwise seen "
               "from above)",
               impl});
  v.field("pitch_deg_per_s", s.pitch_deg_per_s, Range<float>{-1e5f, 1e5f},
          Meta{"oscillating pitch rate; the pitch swings within +-30 degrees", impl});
}

struct BobSpec {
  float amplitude = 0.0f;
  float frequency_hz = 1.0f;
};

template <class V>
void fields(V& v, BobSpec& s) {
  const char* impl = "renderer/script/camera.cpp";
  v.field("amplitude", s.amplitude, Range<float>{0.0f, 1e4f}, Meta{"vertical bobbing amplitude (world units)", impl});
  v.field("frequency_hz", s.frequency_hz, Range<float>{0.0f, 1e3f}, Meta{"bobbing frequency", impl});
}

struct StrafeSpec {
  float speed = 0.0f;
  float distance = 0.0f;
};

template <class V>
void fields(V& v, StrafeSpec& s) {
  const char* impl = "renderer/script/camera.cpp";
  v.field("speed", s.speed, Range<float>{0.0f, 1e7f}, Meta{"sideways speed (units per second)", impl});
  v.field("distance", s.distance, Range<float>{0.0f, 1e7f},
          Meta{"half-width of the back-and-forth strafe (units); 0 strafes without turning back", impl});
}

struct CutSpec {
  int frame = 0;
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f, 0.0f, -1.0f};
};

template <class V>
void fields(V& v, CutSpec& s) {
  const char* impl = "renderer/script/camera.cpp";
  v.field("frame", s.frame, Range<int>{0, 99999}, Meta{"first frame of the new shot", impl});
  v.field("position", s.position, Meta{"camera position from this frame on", impl});
  v.field("target", s.target, Meta{"point the camera faces from this frame on", impl});
}

struct CameraSpec {
  glm::vec3 position{0.0f, 1.6f, 6.0f};
  glm::vec3 target{0.0f, 0.5f, 0.0f};
  float fov_y_deg = 60.0f;
  float near_plane = 0.1f;
  float far_plane = 1000.0f;
  PathSpec path;
  RotateSpec rotate;
  BobSpec bob;
  StrafeSpec strafe;
  std::vector<CutSpec> cuts;
  std::string track;  // recorded poses; replaces position/target/path/rotate/bob/strafe/cuts
  std::string track_camera;
  float track_time_offset_s = 0.0f;
};

template <class V>
void fields(V& v, CameraSpec& s) {
  const char* impl = "renderer/script/camera.cpp";
  v.field("position", s.position, Meta{"initial camera position", impl});
  v.field("target", s.target, Meta{"point the camera initially faces", impl});
  v.field("fov_y_deg", s.fov_y_deg, Range<float>{1.0f, 179.0f}, Meta{"vertical field of view", impl});
  v.field("near", s.near_plane, Range<float>{1e-6f, 1e9f}, Meta{"near clip plane distance", impl});
  v.field("far", s.far_plane, Range<float>{1e-5f, 1e12f}, Meta{"far clip plane distance", impl});
  v.object("path", s.path, Meta{"fly-through path", impl});
  v.object("rotate", s.rotate, Meta{"procedural rotation", impl});
  v.object("bob", s.bob, Meta{"procedural bobbing", impl});
  v.object("strafe", s.strafe, Meta{"procedural strafing", impl});
  v.list("cuts", s.cuts, Meta{"camera cuts (teleports); each flags its frame for history reset", impl});
  const char* track = "renderer/script/tracks.cpp";
  v.field("track", s.track,
          Meta{"recorded camera track (.json, .csv, or an animated camera in a .gltf/.glb), "
               "relative to the case file; replaces position, target, path, rotate, bob, strafe "
               "and cuts, and fov/near/far when the track carries them (docs/tracks.md)",
               track});
  v.field("track_camera", s.track_camera,
          Meta{"name of the camera node of a glTF camera track; may be left out when the file "
               "has exactly one camera node",
               "renderer/script/track_gltf.cpp"});
  v.field("track_time_offset_s", s.track_time_offset_s, Range<float>{-1e6f, 1e6f},
          Meta{"track time replayed at frame 0: frame n samples the track at offset + n / fps",
               track});
}

enum class MoverShape { Cube, Sphere, Gltf };
TAA_ENUM_NAMES(MoverShape, {MoverShape::Cube, "cube"}, {MoverShape::Sphere, "sphere"}, {MoverShape::Gltf, "gltf"})

enum class Repeat { Once, Cyclic, PingPong };
TAA_ENUM_NAMES(Repeat, {Repeat::Once, "once"}, {Repeat::Cyclic, "cyclic"}, {Repeat::PingPong, "ping_pong"})

enum class SpeedUnit { PerSecond, PerFrame };
TAA_ENUM_NAMES(SpeedUnit, {SpeedUnit::PerSecond, "per_second"}, {SpeedUnit::PerFrame, "per_frame"})

struct MoverSpec {
  MoverShape shape = MoverShape::Cube;
  std::string gltf;  // when shape is gltf
  glm::vec3 color{0.85f, 0.25f, 0.2f};
  float size = 1.0f;
  glm::vec3 start{-2.0f, 0.5f, 0.0f};
  glm::vec3 end{2.0f, 0.5f, 0.0f};
  float speed = 1.0f;
  SpeedUnit speed_unit = SpeedUnit::PerSecond;
  Repeat repeat = Repeat::PingPong;
  glm::vec3 rotation_axis{0.0f, 1.0f, 0.0f};
  float rotation_speed_deg = 0.0f;
  bool continuous_rotation = true;
  float animation_speed = 1.0f;
  float animation_offset_s = 0.0f;
  std::vector<std::string> animations;  // names or decimal indices; empty: all play
  std::string track;  // recorded transforms; replaces start/end/speed/repeat/rotation/size
  float track_time_offset_s = 0.0f;
};

template <class V>
void fields(V& v, MoverSpec& s) {
  const char* impl = "renderer/script/movers.cpp";
  v.field("shape", s.shape, Meta{"built-in cube or sphere, or a glTF model", "renderer/scene/procedural.cpp"});
  v.field("gltf", s.gltf, Meta{"glTF model (shape gltf), relative to the case file", "renderer/scene/gltf_loader.cpp"});
  v.field("color", s.color, Meta{"base colour of a built-in shape", "renderer/scene/procedural.cpp"});
  v.field("size", s.size, Range<float>{1e-4f, 1e6f}, Meta{"uniform scale", impl});
  v.field("start", s.start, Meta{"start of the straight-line motion", impl});
  v.field("end", s.end, Meta{"end of the straight-line motion", impl});
  v.field("speed", s.speed, Range<float>{0.0f, 1e7f}, Meta{"speed along start-end", impl});
  v.field("speed_unit", s.speed_unit, Meta{"units of speed: per second or per frame", impl});
  v.field("repeat", s.repeat, Meta{"at the end: stop (once), jump back (cyclic) or reverse (ping_pong)", impl});
  v.field("rotation_axis", s.rotation_axis, Meta{"rotation axis (object space)", impl});
  v.field("rotation_speed_deg", s.rotation_speed_deg, Range<float>{-1e6f, 1e6f},
          Meta{"degrees per second if continuous_rotation, else degrees per unit travelled", impl});
  v.field("continuous_rotation", s.continuous_rotation,
          Meta{"rotate with time, independent of position; otherwise rotation follows the distance "
               "travelled",
               impl});
  v.field("animation_speed", s.animation_speed, Range<float>{0.0f, 1e3f},
          Meta{"playback speed of the glTF model's animations", "renderer/scene/animation.cpp"});
  v.field("animation_offset_s", s.animation_offset_s, Range<float>{-1e6f, 1e6f},
          Meta{"animation time at frame 0: frame n plays offset + speed * n / fps",
               "renderer/scene/animation.cpp"});
  v.field("animations", s.animations,
          Meta{"the glTF model's animations that play together, each a name or a decimal index; "
               "empty: the first and each later one driving nothing an earlier one drives "
               "(docs/gltf.md)",
               "renderer/scene/build_scene.cpp"});
  const char* track = "renderer/script/tracks.cpp";
  v.field("track", s.track,
          Meta{"recorded transforms (.json: its movers[i] for this mover i; .csv: the whole "
               "file), relative to the case file; replaces start, end, speed, speed_unit, "
               "repeat, rotation and size (docs/tracks.md)",
               track});
  v.field("track_time_offset_s", s.track_time_offset_s, Range<float>{-1e6f, 1e6f},
          Meta{"track time replayed at frame 0: frame n samples the track at offset + n / fps",
               track});
}

enum class JitterPattern { None, Halton, Uniform4, Symmetric2, Legacy2, Manual };
TAA_ENUM_NAMES(JitterPattern, {JitterPattern::None, "none"}, {JitterPattern::Halton, "halton"},
               {JitterPattern::Uniform4, "uniform4"}, {JitterPattern::Symmetric2, "symmetric2"},
               {JitterPattern::Legacy2, "legacy2"}, {JitterPattern::Manual, "manual"})

struct JitterSpec {
  JitterPattern pattern = JitterPattern::Halton;
  int length = 8;
  std::vector<glm::vec2> points;
  float scale = 1.0f;
  float rotate_deg = 0.0f;
  int slowdown = 1;
  int lock = -1;
};

template <class V>
void fields(V& v, JitterSpec& s) {
  const char* impl = "renderer/script/jitter.cpp";
  v.field("pattern", s.pattern, Meta{"sub-pixel offset sequence applied to the projection", impl});
  v.field("length", s.length, Range<int>{1, 4096}, Meta{"sequence length of the halton pattern", impl});
  v.field("points", s.points, Meta{"offsets in pixels, each in [-0.5, 0.5], for the manual pattern", impl});
  v.field("scale", s.scale, Range<float>{0.0f, 16.0f}, Meta{"multiplies every offset", impl});
  v.field("rotate_deg", s.rotate_deg, Range<float>{-360.0f, 360.0f},
          Meta{"rotates the pattern about the pixel centre; positive turns +x towards +y (y "
               "down: clockwise on screen)",
               impl});
  v.field("slowdown", s.slowdown, Range<int>{1, 100000}, Meta{"advance the sequence every k frames", impl});
  v.field("lock", s.lock, Range<int>{-1, 4095}, Meta{"always use this step of the sequence; -1 = off", impl});
}

}  // namespace taa::spec
