// The recorded tracks of a case, read and resampled once when the case is loaded.
// Frame evaluation (frame_state.cpp) only indexes them, so it stays pure and cheap.
#pragma once

#include <glm/mat4x4.hpp>
#include <vector>

#include "script/camera.h"
#include "script/track.h"
#include "spec/case_spec.h"

namespace taa::script {

struct Tracks {
  int fps = 0;  // the script.fps and script.frames they were resampled for
  int frames = 0;
  std::vector<CameraFrame> camera;  // one per frame; empty when camera.track is not set
  bool cameraHasFov = false;        // the track replaces camera.fov_y_deg / near / far
  bool cameraHasNear = false;
  bool cameraHasFar = false;
  std::vector<std::vector<glm::mat4>> movers;  // [mover][frame]; empty for a scripted mover
};

// True when camera.track or some movers[i].track is set.
bool usesTracks(const spec::CaseSpec& spec);

// The camera per frame from a checked track: resampled at camera.track_time_offset_s
// + n / fps, lens values the track lacks taken from the case.
std::vector<CameraFrame> cameraTrackFrames(const RawTrack& track, const spec::CaseSpec& spec);

// Mover `mover`'s model matrix per frame from a checked track.
std::vector<glm::mat4> moverTrackFrames(const RawTrack& track, const spec::CaseSpec& spec,
                                        size_t mover);

// Reads every track the case names (paths relative to the case file, confined to its
// folder tree), checks and resamples them. Throws TrackError naming the file and the
// line, key or frame at fault, and the fix.
Tracks loadTracks(const spec::CaseSpec& spec);

}  // namespace taa::script
