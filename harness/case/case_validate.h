// Rules that involve more than one key (a path needs enough points, a frame list
// must lie inside the sequence, ...). Throws CaseError listing every violation.
#pragma once

#include <set>
#include <string>

#include "spec/case_spec.h"

namespace taa::cases {

void validateCase(spec::CaseSpec& spec, const std::set<std::string>& present);

}  // namespace taa::cases
