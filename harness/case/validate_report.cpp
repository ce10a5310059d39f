#include "case/validate_report.h"

#include <nlohmann/json.hpp>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "case/json_reader.h"
#include "case/presets.h"
#include "core/input_file.h"

namespace taa::cases {

std::vector<std::pair<std::string, std::string>> reportProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present) {
  std::vector<std::pair<std::string, std::string>> out;
  const auto& r = spec.report;
  if (present.count("report.ab_presets") && r.ab.empty())
    out.emplace_back("report.ab_presets",
                     "set but report.ab names no preset; set report.ab or remove it");
  const auto& z = r.zoom;
  const bool anyZoomKey = present.count("report.zoom.x") || present.count("report.zoom.y") ||
                          present.count("report.zoom.width") || present.count("report.zoom.height");
  if (anyZoomKey && (z.width == 0 || z.height == 0)) {
    out.emplace_back("report.zoom",
                     "a region needs a width and a height above 0, e.g. {\"x\": 40, \"y\": 20, "
                     "\"width\": 32, \"height\": 18}");
    return out;
  }
  // The output is the eyes side by side (TSCMAA stereo), each render.width wide.
  const int outW = spec.render.width * spec.tscmaa.eyes, outH = spec.render.height;
  if (z.width > 0 && (z.x + z.width > outW || z.y + z.height > outH))
    out.emplace_back("report.zoom", "the region " + std::to_string(z.x) + "," +
                                        std::to_string(z.y) + " " + std::to_string(z.width) + "x" +
                                        std::to_string(z.height) + " leaves the " +
                                        std::to_string(outW) + "x" + std::to_string(outH) +
                                        " output; move or shrink it");
  return out;
}

std::string abCaseJson(const nlohmann::json& root, const spec::CheckedCase& spec) {
  const auto& r = spec.report;
  if (r.ab.empty()) return "";
  const std::string where = spec.file.string() + ": report.ab";
  const auto dir = spec.file.parent_path();
  Presets presets;
  try {
    presets = loadPresets(
        containedRealPath(dir, dir / r.ab_presets, "the case's report.ab_presets"));
  } catch (const InputFileError& e) {
    throw CaseError({spec.file.string() + ": report.ab_presets: " + e.what()});
  } catch (const CaseError& e) {
    std::vector<std::string> problems;
    for (const auto& p : e.problems())
      problems.push_back(spec.file.string() + ": report.ab_presets: " + p);
    throw CaseError(problems);
  }
  const auto it = presets.find(r.ab);
  if (it == presets.end()) {
    std::vector<std::string> known;
    for (const auto& [name, patch] : presets) known.push_back(name);
    const std::string guess = closestMatch(r.ab, known);
    throw CaseError({where + ": no preset '" + r.ab + "' in " + r.ab_presets +
                     (guess.empty() ? "; name one of: " + joinNames(known)
                                    : "; did you mean '" + guess + "'?")});
  }
  nlohmann::json patched = root;
  patched.merge_patch(it->second);
  patched.erase("report");
  const std::string text = patched.dump(2);
  LoadedCase b;
  try {
    b = parseCase(text, spec.file);
  } catch (const CaseError& e) {
    std::vector<std::string> problems;
    for (const auto& p : e.problems())
      problems.push_back(where + " (preset " + r.ab + " merged in): " + p);
    throw CaseError(problems);
  }
  const auto& s = b.spec;
  if (s.render.width != spec.render.width || s.render.height != spec.render.height ||
      s.tscmaa.eyes != spec.tscmaa.eyes || s.script.frames != spec.script.frames)
    throw CaseError({where + ": preset " + r.ab +
                     " changes the output size or the frame count, so its frames "
                     "cannot be compared with the case's; pick a preset that keeps render.width, "
                     "render.height, "
                     "tscmaa.eyes and script.frames"});
  return text;
}

}  // namespace taa::cases
