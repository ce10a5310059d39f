#include "cli/options.h"

namespace taa::cli {

ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& flagNames,
                     const std::set<std::string>& valueNames, const std::string& usage) {
  ParsedArgs out;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") throw HelpRequested(usage);
    if (a.rfind("--", 0) != 0) {
      out.positional.push_back(a);
      continue;
    }
    const auto eq = a.find('=');
    const std::string key = a.substr(0, eq);
    if (flagNames.count(key) && eq == std::string::npos) {
      out.flags.insert(key);
    } else if (valueNames.count(key)) {
      if (eq != std::string::npos) {
        out.values[key] = a.substr(eq + 1);
      } else if (i + 1 < args.size()) {
        out.values[key] = args[++i];
      } else {
        throw UsageError(key + " needs a value\nusage: " + usage);
      }
    } else {
      throw UsageError("unknown option " + a + "\nusage: " + usage);
    }
  }
  return out;
}

}  // namespace taa::cli
