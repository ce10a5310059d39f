#include "cli/options.h"

namespace taa::cli {

ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& flagNames,
                     const std::set<std::string>& valueNames, const std::string& usage) {
  ParsedArgs out;
  for (size_t i = 0; i < args.size(); ++i) {
    std::string a = args[i];
    if (a == "--help" || a == "-h") throw HelpRequested(usage);
    // -j N and -jN, make's spelling, for commands that take --jobs.
    if (valueNames.count("--jobs") && a.rfind("-j", 0) == 0)
      a = a.size() == 2 ? "--jobs" : "--jobs=" + a.substr(2);
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
