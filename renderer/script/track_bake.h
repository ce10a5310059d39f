// Baking: a case's camera and movers, as the script (or its own tracks) moves them,
// written as a JSON track at the case's fps, so a golden no longer depends on the
// curve code. Replaying the baked track reproduces every frame bit for bit.
#pragma once

#include <string>

#include "script/track_json.h"
#include "spec/case_spec.h"

namespace taa::script {

// Every frame of the case: the camera's exact double pose (its rotation matrix as a
// basis, with its quaternion beside it for readers), lens and cut flag, and each
// mover's float model matrix. `description` goes into the file.
TrackFile bakeTrack(const spec::CaseSpec& spec, const std::string& description);

// bakeTrack() written as JSON, after checking that replaying the text gives every
// FrameState camera and mover bit for bit; throws std::logic_error if it would not.
std::string bakeTrackJson(const spec::CaseSpec& spec, const std::string& description);

// `spec` with its camera and movers driven by `track` (as if camera.track and every
// movers[i].track named it) in place of their scripts: what a replay case renders.
spec::CaseSpec replaySpec(const spec::CaseSpec& spec, const TrackFile& track);

}  // namespace taa::script
