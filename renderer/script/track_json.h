// The JSON track format ("format": "taa-track", "version": 1): a camera and any number
// of movers, each a list of frames, either at a fixed "fps" or with a time "t" each.
// It is what `taa-harness bake` writes; docs/tracks.md documents every key.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "script/track.h"

namespace taa::script {

struct TrackFile {
  std::string description;
  double fps = 0.0;  // > 0: frames[k] is at k / fps and has no "t"; 0: every frame has "t"
  std::optional<RawTrack> camera;
  std::vector<RawTrack> movers;  // movers[i] drives the case's movers[i]
};

// Parses the text of `file`; messages name the file and the key path
// (camera.frames[3].orientation). Only per-value problems are found here;
// checkTrack() does the rest.
TrackFile parseJsonTrack(const std::string& text, const std::string& file);

// Writes `track` so that parseJsonTrack() reads back every value bit for bit: doubles
// (positions, quaternions) in shortest round-trip form, float lenses and matrices
// as the shortest decimal that rounds back to the same float. One frame per line.
std::string writeJsonTrack(const TrackFile& track);

}  // namespace taa::script
