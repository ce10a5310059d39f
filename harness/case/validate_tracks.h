// Case rules for recorded tracks (camera.track, movers[].track). A track replaces the
// settings it drives, so setting both is an error rather than a setting silently
// ignored; tracks are read once here, when the case is loaded.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/case_spec.h"

namespace taa::cases {

// (key path, message with the fix) for every violated rule that needs no file read.
std::vector<std::pair<std::string, std::string>> trackProblems(
    const spec::CaseSpec& spec, const std::set<std::string>& present);

// Reads and resamples the tracks into spec.tracks (nothing when the case has none).
// Throws CaseError for a bad track (naming the case key, the track file and its line,
// key or frame) and for lens keys that a track carrying them replaces.
void loadCaseTracks(spec::CaseSpec& spec, const std::set<std::string>& present);

}  // namespace taa::cases
