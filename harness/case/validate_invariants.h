// Case rules for checks.invariants: every listed invariant must apply to the case (it checks
// a technique the case enables), none is listed twice, and an invariant's parameter object
// (checks.no_ghosting, ...) is set only when the invariant is listed.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/checked_case.h"

namespace taa::cases {

// (key path, message) per problem.
std::vector<std::pair<std::string, std::string>> invariantProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present);

}  // namespace taa::cases
