#include "case/presets.h"

#include <nlohmann/json.hpp>

#include "case/case_error.h"
#include "invariants/registry.h"

namespace taa::cases {

namespace fs = std::filesystem;

Presets loadPresets(const fs::path& file) {
  const auto j = readJsonFile(file);
  if (!j.is_object())
    throw CaseError({file.string() + ": expected an object {\"preset\": {patch}, ...}"});
  Presets out;
  for (const auto& [name, patch] : j.items()) {
    if (!patch.is_object())
      throw CaseError(
          {file.string() + ": " + name + ": a preset is a JSON object merged into the case"});
    out[name] = patch;
  }
  return out;
}

LoadedCase presetLane(const nlohmann::json& base, const nlohmann::json& patch,
                      const fs::path& caseFile, const fs::path& presetsDir,
                      std::vector<std::string>* notApplicable) {
  nlohmann::json merged = base;
  merged.merge_patch(patch);
  const nlohmann::json checks = merged.value("checks", nlohmann::json::object());
  merged.erase("checks");
  LaneParse lane;
  lane.capabilitiesUnchecked = true;
  // A preset's own shader: beside the case as documented, or else beside its presets file.
  if (patch.contains("taa") && patch["taa"].is_object() && patch["taa"].contains("shader") &&
      patch["taa"]["shader"].is_string() && !presetsDir.empty()) {
    const std::string shader = patch["taa"]["shader"].get<std::string>();
    std::error_code ec;
    if (!fs::exists(caseFile.parent_path() / shader, ec) && fs::exists(presetsDir / shader, ec))
      lane.shaderRoot = presetsDir;
  }
  LoadedCase loaded = parseCase(merged.dump(2), caseFile, lane);
  if (notApplicable && checks.contains("invariants") && checks["invariants"].is_array())
    for (const auto& name : checks["invariants"])
      if (name.is_string())
        if (const std::string why = invariants::inapplicable(name.get<std::string>(), loaded.spec);
            !why.empty())
          notApplicable->push_back(name.get<std::string>() + ": " + why);
  return loaded;
}

}  // namespace taa::cases
