#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "api/device.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "score/score.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kScoreUsage =
    "taa-harness score SHADER [--params NAME=V,...] [--name LANE] [SHADER ...] [--lanes FILE]\n"
    "                  [--cases DIR] [--out DIR] [--quick] [--device NAME]\n"
    "  runs each lane (a compute shader including taa_user.h or taa_user.hlsli, docs/user-taa.md,\n"
    "  with the --params and --name that follow it; or the lanes of FILE: {\"name\": {\"shader\":\n"
    "  \"x.hlsl\", \"shader_params\": [...]}, ...}) over every case of DIR (default: cases) where a\n"
    "  resolve applies (taa.mode full, no debug view), next to the built-in resolve at its\n"
    "  defaults, all against one supersampled reference: FLIP, RMSE, flicker, convergence frame,\n"
    "  ghosting (mover cases), non-finite samples, GPU ms per frame, in one table. --quick scores\n"
    "  the first 3 such cases only. Writes DIR/score.md, score.json, score.html and score.svg\n"
    "  (default DIR: out/score). Every figure but ms/frame is deterministic.";

struct LaneArgs {
  fs::path shader;
  std::string params, name;
};
}  // namespace

int cmdScore(const Args& args) {
  // Lanes are positional with their own options, so the arguments are read in order here.
  std::vector<LaneArgs> lanes;
  Args rest;
  fs::path lanesFile;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool laneOption = a == "--params" || a == "--name";
    if (laneOption || a == "--lanes") {
      if (i + 1 >= args.size() || args[i + 1].empty())
        throw UsageError(a + " needs a value\nusage: " + kScoreUsage);
      if (a == "--lanes") {
        lanesFile = args[++i];
        continue;
      }
      if (lanes.empty()) throw UsageError(a + " follows no SHADER\nusage: " + kScoreUsage);
      std::string& field = a == "--params" ? lanes.back().params : lanes.back().name;
      if (!field.empty()) throw UsageError(a + " given twice for " + lanes.back().shader.string());
      field = args[++i];
      continue;
    }
    if (a == "--cases" || a == "--out" || a == "--device") {
      rest.push_back(a);
      if (i + 1 < args.size()) rest.push_back(args[++i]);
      continue;
    }
    if (!a.empty() && a[0] != '-') {
      lanes.push_back({a, "", ""});
      continue;
    }
    rest.push_back(a);
  }
  const auto a = parseArgs(rest, {"--quick"}, {"--cases", "--out", "--device"}, kScoreUsage);
  if (!a.positional.empty() || (lanes.empty() && lanesFile.empty()))
    throw UsageError(std::string("usage: ") + kScoreUsage);
  score::ScoreOptions o;
  std::error_code ec;
  for (const auto& l : lanes) {
    // Only existence here: the compiler says what else is wrong (a FIFO, a link loop).
    if (!fs::exists(fs::symlink_status(l.shader, ec)))
      throw UsageError(l.shader.string() + ": no such shader file");
    // A lane is named after its shader's stem; two shaders of one stem (a GLSL resolve and its
    // HLSL twin) by their file names, one shader given twice also by its parameters.
    const bool repeated = std::count_if(lanes.begin(), lanes.end(),
                                        [&](const LaneArgs& x) { return x.shader == l.shader; }) > 1;
    const bool twin = std::any_of(lanes.begin(), lanes.end(), [&](const LaneArgs& x) {
      return x.shader != l.shader && x.shader.stem() == l.shader.stem();
    });
    score::LaneSpec lane = score::shaderLane(l.shader, l.params, l.name, repeated);
    if (twin && l.name.empty()) lane.name.replace(0, l.shader.stem().string().size(), l.shader.filename().string());
    o.lanes.push_back(std::move(lane));
  }
  if (!lanesFile.empty())
    for (auto& l : score::loadLanes(lanesFile)) o.lanes.push_back(std::move(l));
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
  std::cout << "scorecard of " << s.lanes.size() << " lanes on " << s.device << " ("
            << s.cases.size() << " cases, " << s.skipped.size() << " skipped):\n"
            << score::scoreMarkdown(s) << "wrote " << (out / "score.md").string()
            << ", score.json, score.html, score.svg\n"
            << "references: " << s.references.rendered << " rendered, " << s.references.fromDisk
            << " from disk, " << s.references.reused << " reused\n";
  return kPass;
}

}  // namespace taa::cli
