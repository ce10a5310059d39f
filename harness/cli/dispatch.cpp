#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>
#include <map>

#include "api/device.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/errors.h"

namespace taa::cli {

namespace {
struct Command {
  int (*run)(const Args&);
  const char* summary;
};

const std::map<std::string, Command>& commands() {
  static const std::map<std::string, Command> table = {
      {"validate", {cmdValidate, "check case files; --print shows every value in force"}},
      {"new-case", {cmdNewCase, "write a case for a glTF scene with a camera that frames its bounds"}},
      {"sweep", {cmdSweep, "error against run time of technique presets on one script (CSV, table, SVG, report)"}},
      {"score", {cmdScore, "scorecard of your own resolve shader over the case library next to the built-in one"}},
      {"techniques", {cmdTechniques, "list every setting (--json for type, range, default, shader; --markdown for the docs table)"}},
      {"render", {cmdRender, "render a case headlessly: EXR + PNG per requested frame, sha256 per frame"}},
      {"merge", {cmdMerge, "join the outputs of run --shard I/N into one results.json, junit.xml and report"}},
      {"run", {cmdRun, "render cases, compare with goldens, run invariants; results.json, junit.xml, report.html"}},
      {"bless", {cmdBless, "write a case's goldens (atomic) with the reason, after its invariants pass"}},
      {"bake", {cmdBake, "write a case's camera and mover poses per frame as a track (replays bit for bit)"}},
      {"coverage", {cmdCoverage, "which taa.* setting values and resolve shader branches the cases reach, and the holes"}},
      {"compare", {cmdCompare, "metrics (max abs, RMSE, PSNR, FLIP, HDR-FLIP) of two image files; bounds give exit 1"}},

  };
  return table;
}

void usage(std::ostream& out) {
  out << "usage: taa-harness <command> [args]\n\ncommands:\n";
  // Names padded to the longest (and two spaces beyond), so a longer name never wraps.
  size_t width = 0;
  for (const auto& entry : commands()) width = std::max(width, entry.first.size());
  for (const auto& [name, cmd] : commands())
    out << "  " << name << std::string(std::max<size_t>(width + 2, 12) - name.size(), ' ')
        << cmd.summary << "\n";
  out << "\n  --version   the version and the folder SPIR-V is loaded from\n";
  out << "\nexit codes: 0 pass, 1 regression, 2 bad input, 3 environment (no Vulkan device, ...)\n";
}
}  // namespace

int dispatch(int argc, char** argv) {
  if (argc < 2) {
    usage(std::cerr);
    return kBadInput;
  }
  const std::string name = argv[1];
  if (name == "-h" || name == "--help" || name == "help") {
    usage(std::cout);
    return kPass;
  }
  if (name == "--version" || name == "version") {
    // Where the SPIR-V comes from tells an installed binary from one in a build tree.
    std::cout << "taa-harness " << TAA_VERSION << "\nshaders: " << shaderFolder() << "\n";
    return kPass;
  }
  const auto it = commands().find(name);
  if (it == commands().end()) {
    std::cerr << "taa-harness: unknown command '" << name << "'\n";
    usage(std::cerr);
    return kBadInput;
  }
  // Every error is of one of two kinds (core/errors.h), and the kind is the exit code.
  try {
    return it->second.run(Args(argv + 2, argv + argc));
  } catch (const HelpRequested& e) {
    std::cout << "usage: " << e.what() << "\n";
    return kPass;
  } catch (const InputError& e) {
    std::cerr << e.report(name) << "\n";
    return kBadInput;
  } catch (const EnvironmentError& e) {
    std::cerr << e.report(name) << "\n";
    return kEnvironment;
  } catch (const std::exception& e) {
    // Of neither kind: a file-system call that threw, memory, or a bug. Not the input's fault.
    std::cerr << "error: " << e.what() << "\n";
    return kEnvironment;
  }
}

}  // namespace taa::cli
