// Cross-key rules of the temporal resolve: a technique's parameter set without the
// technique, or a combination the resolve cannot honour, is an error rather than a
// setting silently ignored.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/case_spec.h"

namespace taa::cases {

// (key path, message with the fix) for every violated rule.
std::vector<std::pair<std::string, std::string>> taaProblems(const spec::CaseSpec& spec,
                                                              const std::set<std::string>& present);

// Marks taa.moving active when the case sets it and gives every float it leaves out the
// still value, so the blend moves only what the case names (call after validation).
void resolveTaaMoving(spec::TaaSpec& taa, const std::set<std::string>& present);

}  // namespace taa::cases
