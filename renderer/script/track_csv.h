// Engine captures as CSV: a header line naming the columns, then one sample per line;
// '#' starts a comment line, and "# fps: N" gives the rate of a frame-numbered capture.
// docs/tracks.md lists the columns.
#pragma once

#include <string>

#include "script/track.h"

namespace taa::script {

// Parses the text of `file` (named in every message as file:line). Only per-value
// problems are found here; checkTrack() does the rest.
RawTrack parseCsvTrack(const std::string& text, const std::string& file, TrackSubject subject);

}  // namespace taa::script
