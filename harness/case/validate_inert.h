// Case rules for settings that only act beside another: a camera path's shape without its
// points, a bob's frequency without its amplitude, a mover's rotation axis without a rotation,
// and the like. Each was accepted and ignored until the settings audit (docs/settings-audit.md)
// rendered it; now it is refused with the setting it needs.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/case_spec.h"

namespace taa::cases {

// (key path, message with the fix) for every key set where it cannot act.
std::vector<std::pair<std::string, std::string>> inertProblems(
    const spec::CaseSpec& spec, const std::set<std::string>& present);

}  // namespace taa::cases
