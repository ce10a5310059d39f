// What a case gives the reference pass, as one string: the part of a reference frame's cache
// key (api/reference_cache.h) that comes from the case file. The renderer adds each frame's
// own inputs (uniforms, draws, shadow cascades), so settings that reach the reference only
// through the frame state (camera, script, jitter) are left out here; so are the settings the
// reference pass never reads (the resolve, post passes, checks, the report).
#pragma once

#include <string>

#include "spec/checked_case.h"

namespace taa::run {

// The case's resolved settings less the ones above, and the case's folder (files named in the
// case are relative to it; within one run a path names one content).
std::string referenceKey(const spec::CaseSpec& spec);

}  // namespace taa::run
