// Case rules for the `report` section: the zoom region lies inside the output, and an A/B
// preset (report.ab) is resolved when the case is loaded, so a missing presets file, an
// unknown preset or a patch that breaks the case is bad input before anything renders.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/checked_case.h"

namespace taa::cases {

// (key path, message with the fix) for every violated rule that needs no file read.
std::vector<std::pair<std::string, std::string>> reportProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present);

// The B side of report.ab as case JSON: the case file's JSON `root` with the preset merged
// in and the report section removed (B is not compared again), checked to parse as a case
// with the same output size and frame count. "" when report.ab is empty. Throws CaseError
// naming the case file, the key and the fix.
std::string abCaseJson(const nlohmann::json& root, const spec::CheckedCase& spec);

}  // namespace taa::cases
