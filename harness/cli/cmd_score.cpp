#include <unistd.h>

#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "device.h"
#include "score/score.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kScoreUsage =
    "taa-harness score SHADER [--cases DIR] [--out DIR] [--quick] [--device NAME]\n"
    "  runs your resolve (a compute shader including taa_user.h, docs/user-taa.md) over every case "
    "of\n"
    "  DIR (default: cases) where a resolve applies (taa.mode full, no debug view), next to the\n"
    "  built-in resolve at its defaults, both against one supersampled reference: FLIP, RMSE,\n"
    "  flicker, convergence frame, ghosting (mover cases), non-finite samples, GPU ms per frame.\n"
    "  --quick scores the first 3 such cases only. Writes DIR/score.md, score.json, score.html "
    "and\n"
    "  score.svg (default DIR: out/score). Every figure but ms/frame is deterministic.";
}  // namespace

int cmdScore(const Args& args) {
  const auto a = parseArgs(args, {"--quick"}, {"--cases", "--out", "--device"}, kScoreUsage);
  if (a.positional.size() != 1) throw UsageError(std::string("usage: ") + kScoreUsage);
  score::ScoreOptions o;
  o.shader = a.positional[0];
  // Only existence here: the compiler says what else is wrong (a FIFO, a link loop).
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(o.shader, ec)))
    throw UsageError(o.shader.string() + ": no such shader file");
  o.casesDir = a.value("--cases", "cases");
  if (!fs::is_directory(o.casesDir, ec))
    throw UsageError(o.casesDir.string() + ": no such folder of cases; pass --cases DIR");
  o.maxCases = a.flags.count("--quick") ? 3 : 0;
  if (isatty(STDERR_FILENO))
    o.progress = [](const std::string& name, const std::string& lane, int f, int frames) {
      std::cerr << "\r" << name << " (" << lane << ") frame " << f + 1 << "/" << frames << "\033[K"
                << std::flush;
    };
  const fs::path out = a.value("--out", "out/score");
  DeviceOptions co;
  co.device = a.value("--device");
  Device device(co);
  const score::Scorecard s = score::runScore(device, o);
  if (o.progress) std::cerr << "\r\033[K";
  score::writeScorecard(out, s);
  std::cout << "scorecard of " << s.shader << " on " << s.device << " (" << s.cases.size()
            << " cases, " << s.skipped.size() << " skipped):\n"
            << score::scoreMarkdown(s) << "wrote " << (out / "score.md").string()
            << ", score.json, score.html, score.svg\n";
  return kPass;
}

}  // namespace taa::cli
