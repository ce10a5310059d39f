#include <iostream>
#include <nlohmann/json.hpp>

#include "api/scene_loading.h"
#include "case/case_error.h"
#include "case/case_loader.h"
#include "case/settings_table.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/errors.h"

namespace taa::cli {

// Everything render reads before it needs a device: the case, its tracks and user shader
// (loadCase), its scene, movers and debug image with their checks (buildCaseScene). Each file's
// problems are reported and the next file is still checked.
int cmdValidate(const Args& args) {
  static const char* kUsage = "taa-harness validate [--print] CASE...";
  const auto a = parseArgs(args, {"--print"}, {}, kUsage);
  if (a.positional.empty()) throw UsageError(std::string("no case given\nusage: ") + kUsage);
  const bool print = a.has("--print");
  int bad = 0;
  for (const auto& f : a.positional) {
    try {
      const auto loaded = cases::loadCase(f);
      buildCaseScene(loaded.spec);
      if (print)
        std::cout << cases::resolvedJson(loaded.spec).dump(2) << "\n";
      else
        std::cout << f << ": ok\n";
    } catch (const cases::CaseError& e) {
      for (const auto& p : e.problems()) std::cerr << "error: " << p << "\n";
      ++bad;
    } catch (const InputError& e) {  // the scene, a track, the shader, an image: exit 2
      std::cerr << "error: " << e.what() << "\n";
      ++bad;
    }
  }
  if (bad > 0 && a.positional.size() > 1)
    std::cerr << bad << " of " << a.positional.size() << " case files have problems\n";
  return bad > 0 ? kBadInput : kPass;
}

int cmdTechniques(const Args& args) {
  static const char* kUsage = "taa-harness techniques [--json | --markdown]";
  const auto a = parseArgs(args, {"--json", "--markdown"}, {}, kUsage);
  if (!a.positional.empty()) throw UsageError("unexpected argument " + a.positional[0] + "\nusage: " + kUsage);
  if (a.has("--json") && a.has("--markdown")) throw UsageError(std::string("choose --json or --markdown\nusage: ") + kUsage);
  const auto rows = cases::settingsSchema();
  if (a.has("--json")) {
    std::cout << rows.dump(2) << "\n";
    return kPass;
  }
  if (a.has("--markdown")) {  // docs/case-format.md's "Every key" table
    std::cout << cases::settingsMarkdownTable(rows);
    return kPass;
  }
  for (const auto& r : rows) {
    std::cout << r["key"].get<std::string>() << " (" << r["type"].get<std::string>() << ", default "
              << r["default"].dump() << ")";
    if (r.contains("range")) std::cout << " range " << r["range"].dump();
    if (r.contains("allowed")) std::cout << " one of " << r["allowed"].dump();
    std::cout << "\n    " << r["doc"].get<std::string>();
    if (!r["impl"].get<std::string>().empty()) std::cout << "  [" << r["impl"].get<std::string>() << "]";
    std::cout << "\n";
  }
  return kPass;
}

}  // namespace taa::cli
