#include "cli/options.h"

#include <cmath>
#include <sstream>

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
      // No option means anything by an empty value ("--out ''" would write into the working
      // folder, "--max ''" would check nothing).
      if (out.values[key].empty())
        throw UsageError(key + " is given an empty value; give one or leave the option out\nusage: " +
                         usage);
    } else {
      throw UsageError("unknown option " + a + "\nusage: " + usage);
    }
  }
  return out;
}

double numberOption(const ParsedArgs& a, const std::string& key, double lo, double hi,
                    bool whole) {
  const std::string text = a.value(key);
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(v))
    throw UsageError(key + ": '" + text + "' is not a number");
  if (whole && v != std::floor(v))
    throw UsageError(key + ": '" + text + "' is not a whole number");
  if (v < lo || v > hi) {
    std::ostringstream range;
    range << "[" << lo << ", " << hi << "]";
    throw UsageError(key + ": " + text + " is outside " + range.str());
  }
  return v;
}

}  // namespace taa::cli
