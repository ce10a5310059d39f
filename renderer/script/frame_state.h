// Everything the renderer needs to know about one frame, as a pure function of
// the case and the frame index: no clock, no randomness, no hidden state, so any
// frame can be evaluated alone, twice, or out of order with identical results.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "script/camera.h"
#include "spec/case_spec.h"

namespace taa::script {

struct CameraState {
  glm::vec3 position{0.0f};
  glm::mat4 view{1.0f};            // world -> view
  glm::mat4 projection{1.0f};      // un-jittered, Vulkan clip, Y down, reversed Z
  glm::mat4 viewProjection{1.0f};  // projection * view
  float fovY = 1.0f;               // radians
  float aspect = 1.0f;             // output width / height
  float nearPlane = 0.1f, farPlane = 1000.0f;
};

struct FrameState {
  int frame = 0;
  double time = 0.0;         // frame / fps, the only clock
  glm::ivec2 renderSize{1};  // render resolution this frame: round(output/upsample), times the
                             // scale schedule's scale, at least 1
  float renderScale = 1.0f;  // the scale schedule's value in force (1 without schedule)
  CameraState camera, prevCamera;  // prev = frame-1; at frame 0 and at a cut prev equals current
  glm::vec2 jitter{0.0f};          // render pixels, y down: the image moves by this offset
  glm::mat4 jitteredProjection{1.0f};
  // World transform per mover; prev = frame-1 (frame 0: same). Not reset by camera cuts.
  std::vector<glm::mat4> movers, prevMovers;
  std::vector<double> moverAnimTime;  // seconds into each mover's animation
  std::vector<double> prevMoverAnimTime;  // the same at frame - 1 (frame 0: same)
  // Seconds into the world glTF's animations (scene.animation_offset_s + speed * time),
  // now and at frame - 1 (frame 0: same).
  double worldAnimTime = 0.0, prevWorldAnimTime = 0.0;
  bool cameraCut = false;             // a camera cut starts at this frame
  bool resetHistory = false;          // cut, frame 0, or script.reset_history_at
};

// The scale schedule's value at `frame`: the key with the greatest frame <= frame
// (the later listed on ties), 1 before the first key or without a schedule.
float renderScaleAt(const spec::RenderSpec& render, int frame);

// Render resolution: lround(output / upsample) per axis (in float, as the case
// validator computes it), times `scale`, rounded again, at least 1.
glm::ivec2 renderSizeFor(const spec::RenderSpec& render, float scale);

// The camera's pose, lens and cut flag at `frame`: from the loaded camera track when
// camera.track is set (spec.tracks), else from the script.
CameraFrame cameraFrame(const spec::CaseSpec& spec, int frame);

// Throws std::out_of_range for frame < 0; frames past script.frames are allowed
// (the script simply continues) unless the case replays recorded tracks, which end
// there. A case with tracks needs spec.tracks loaded for its fps and frames (the
// case loader does that), else std::logic_error.
FrameState frameState(const spec::CaseSpec& spec, int frame);

}  // namespace taa::script
