// Resampling a recorded track to a case's fixed timestep. Frame n replays the track
// at T(n) = offset + n / fps. A sample whose time equals T(n) is used as it is (so a
// track recorded at the case's rate replays exactly); otherwise the two samples
// around T(n) are blended: position, scale and lens linearly, orientation by
// spherical-linear interpolation along the shorter arc. A cut (teleport) is never
// blended across: the earlier sample holds until the cut's time.
#pragma once

#include <vector>

#include "script/track.h"

namespace taa::script {

// One sample per frame n in [0, frames); sample n's `cut` is set when a cut sample
// lies in (T(n-1), T(n)]. Throws TrackError when some T(n) is outside the track
// (a track shorter than the case), naming the frame, the time and the fix.
std::vector<TrackSample> resampleTrack(const RawTrack& track, double offsetS, int fps, int frames);

// The blend of `a` and `b` at fraction s in [0, 1] (no cut handling, no matrix).
TrackSample interpolateSamples(const TrackSample& a, const TrackSample& b, double s);

}  // namespace taa::script
