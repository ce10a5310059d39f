// A case's recorded tracks as the harness sees them: read once when the case loads and kept
// in spec.tracks for the renderer, never looked into; and a case's motion baked to a track.
// script/'s track readers and resampling stay inside renderer/.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "api/loader_errors.h"
#include "spec/case_spec.h"

namespace taa {

struct CaseTracks {
  std::shared_ptr<const script::Tracks> tracks;  // for spec.tracks; null: the case names none
  // The camera keys ("fov_y_deg", "near", "far") the camera track gives for every frame, so the
  // case's own value would be ignored.
  std::vector<std::string> lensKeys;
};

// Every track the case names (camera.track, movers[i].track), read and resampled
// (script::loadTracks). Throws script::TrackError naming the file, the line, key or frame at
// fault, and the fix.
CaseTracks readCaseTracks(const spec::CaseSpec& spec);

// The case's camera and movers, as its script or tracks move them, as a JSON track that
// replays every frame bit for bit (script::bakeTrackJson); `description` goes into the file.
std::string bakeCaseTrack(const spec::CaseSpec& spec, const std::string& description);

}  // namespace taa
