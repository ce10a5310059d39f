// Small argument parser shared by the subcommands: flags, valued options and
// positional arguments, with an error (exit 2) for anything unknown.
#pragma once

#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"

namespace taa::cli {

// A command line that is wrong: bad input, printed after the command's name.
class UsageError : public InputError {
 public:
  using InputError::InputError;
  std::string report(const std::string& command) const override {
    return "taa-harness " + command + ": " + what();
  }
};

// --help or -h anywhere: the command's usage goes to stdout and the exit code is 0.
class HelpRequested : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ParsedArgs {
  std::set<std::string> flags;
  std::map<std::string, std::string> values;
  std::vector<std::string> positional;

  bool has(const std::string& flag) const { return flags.count(flag) > 0; }
  std::string value(const std::string& key, const std::string& fallback = "") const {
    const auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
  }
};

// `flagNames` take no value; `valueNames` take the next argument (or --key=value), which
// may not be empty; where `valueNames` holds --jobs, -j N and -jN mean --jobs N.
// Throws HelpRequested (what(): the usage) for --help or -h, UsageError for anything unknown.
ParsedArgs parseArgs(const std::vector<std::string>& args, const std::set<std::string>& flagNames,
                     const std::set<std::string>& valueNames, const std::string& usage);

// The value of the numeric option `key` (which must be present), checked to be a finite
// number in [lo, hi], whole if `whole`; throws UsageError naming the option and the range.
// Every numeric option goes through it: a value the code cannot afford (a FLIP kernel a
// million pixels wide) is refused, not attempted.
double numberOption(const ParsedArgs& a, const std::string& key, double lo, double hi,
                    bool whole = false);

}  // namespace taa::cli
