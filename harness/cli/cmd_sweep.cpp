#include <nlohmann/json.hpp>
#include <unistd.h>

#include <filesystem>
#include <iostream>
#include <sstream>

#include "api/device.h"
#include "case/presets.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/input_file.h"
#include "cli/batch_args.h"
#include "sweep/sweep.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kSweepUsage =
    "taa-harness sweep CASE --presets A,B,C [--presets-file FILE] [--from-frame N] [--out DIR] [--device NAME]\n"
    "  replays CASE once per preset (a JSON merge patch from FILE, default cases/presets/presets.json\n"
    "  next to the case folder) and measures each against the supersampled reference, rendered once:\n"
    "  FLIP mean, RMSE and flicker over frames N.., and median GPU ms of the TAA passes and the frame.\n"
    "  Writes DIR/sweep.csv, frames.csv, sweep.md, sweep.svg and report.html (default DIR: out/sweep/CASE).";

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}
}  // namespace

int cmdSweep(const Args& args) {
  const auto a = parseArgs(args, {}, {"--presets", "--presets-file", "--from-frame", "--out", "--device"}, kSweepUsage);
  if (a.positional.size() != 1 || !a.values.count("--presets")) throw UsageError(std::string("usage: ") + kSweepUsage);
  const fs::path caseFile = a.positional[0];
  std::error_code ec;  // a link loop is the case reader's to report (exit 2), not an exception here
  if (!fs::exists(fs::symlink_status(caseFile, ec)))
    throw UsageError(caseFile.string() + ": no such case file");
  fs::path presetsFile = a.value("--presets-file");
  if (presetsFile.empty()) {
    // Default: presets/presets.json in the nearest folder named "cases" above the case.
    for (fs::path p = fs::absolute(caseFile).parent_path(); !p.empty() && p != p.root_path(); p = p.parent_path())
      if (p.filename() == "cases") {
        presetsFile = p / "presets" / "presets.json";
        // Found, not named: it must lie in that cases folder after resolving links.
        try {
          containedRealPath(p, presetsFile, "the default presets file");
        } catch (const InputFileError& e) {
          throw UsageError(std::string(e.what()) + "; or pass --presets-file");
        }
        break;
      }
    if (presetsFile.empty()) throw UsageError(caseFile.string() + " is not under a cases/ folder; pass --presets-file");
  }
  const auto presets = cases::loadPresets(presetsFile);
  const auto names = split(a.value("--presets"));
  sweep::SweepOptions options;
  options.presetsDir = fs::absolute(presetsFile).parent_path();
  if (a.values.count("--from-frame"))
    options.fromFrame = int(numberOption(a, "--from-frame", 0, 99999, true));
  if (isatty(STDERR_FILENO))
    options.progress = [](const std::string& preset, int f, int frames) {
      std::cerr << "\r" << preset << " frame " << f + 1 << "/" << frames << "\033[K" << std::flush;
    };
  const fs::path out = a.value("--out", (fs::path("out/sweep") / caseFile.stem()).string());
  refuseOutputInGoldens(out, run::defaultGoldensRoot(caseFile));
  DeviceOptions co;
  co.device = a.value("--device");
  Device device(co);
  const auto result = sweep::runSweep(device, caseFile, presets, names, options);
  if (options.progress) std::cerr << "\r\033[K";
  sweep::writeSweep(out, result);
  std::cout << "sweep of " << result.caseName << " on " << result.device << ", frames " << result.fromFrame << ".."
            << result.frames - 1 << ":\n"
            << sweep::markdownTable(result) << "wrote " << (out / "sweep.csv").string() << ", sweep.md, sweep.svg, "
            << (out / "report.html").string() << "\n";
  return kPass;
}

}  // namespace taa::cli
