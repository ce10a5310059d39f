// Named presets (JSON merge patches, RFC 7386, of a case file) and the lane a preset makes of
// a case: what the sweep replays per preset and report.ab's B side is chosen from.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <vector>

#include "case/case_loader.h"

namespace taa::cases {

using Presets = std::map<std::string, nlohmann::json>;

// Reads a presets file ({"name": {patch}, ...}); CaseError naming the file on bad input.
Presets loadPresets(const std::filesystem::path& file);

// The case file's JSON with a preset merged in, parsed as a lane: its checks dropped (the
// invariants it cannot meet go to `notApplicable`), its taa.shader found beside the case or
// else in `presetsDir`, a missing capability left for the caller to skip. CaseError when the
// merged case is invalid.
LoadedCase presetLane(const nlohmann::json& base, const nlohmann::json& patch,
                      const std::filesystem::path& caseFile,
                      const std::filesystem::path& presetsDir,
                      std::vector<std::string>* notApplicable = nullptr);

}  // namespace taa::cases
