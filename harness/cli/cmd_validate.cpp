#include <iostream>

#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"

namespace taa::cli {

int cmdValidate(const Args& args) {
  bool print = false;
  std::vector<std::string> files;
  for (const auto& a : args) {
    if (a == "--print") {
      print = true;
    } else if (!a.empty() && a[0] == '-') {
      std::cerr << "validate: unknown option " << a << "\nusage: taa-harness validate [--print] CASE...\n";
      return kBadInput;
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) {
    std::cerr << "usage: taa-harness validate [--print] CASE...\n";
    return kBadInput;
  }
  for (const auto& f : files) {
    const auto loaded = cases::loadCase(f);
    if (print)
      std::cout << cases::resolvedJson(loaded.spec).dump(2) << "\n";
    else
      std::cout << f << ": ok\n";
  }
  return kPass;
}

int cmdTechniques(const Args& args) {
  const auto rows = cases::settingsSchema();
  if (!args.empty() && args[0] == "--json") {
    std::cout << rows.dump(2) << "\n";
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
