// Rules that involve more than one key (a path needs enough points, a frame list
// must lie inside the sequence, ...). Throws CaseError listing every violation.
#pragma once

#include <set>
#include <string>

#include "spec/checked_case.h"

namespace taa::cases {

// Checks every rule, puts the case in canonical form and loads its recorded tracks
// into spec.tracks (once per case; frame evaluation only indexes them).
void validateCase(spec::CheckedCase& spec, const std::set<std::string>& present);

// Why a case's asset path (scene, model or track) is refused: a URI, an absolute
// path, or one leaving the case's folder tree; "" when it is fine.
std::string assetPathProblem(const std::string& value);

}  // namespace taa::cases
