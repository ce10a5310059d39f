#include <filesystem>
#include <iostream>

#include "api/tracks.h"
#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/output_file.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kBakeUsage =
    "taa-harness bake CASE --out TRACK.json\n"
    "  writes the case's camera (exact pose, lens, cut flags) and every mover's transform\n"
    "  for each of its frames at its fps; a case with \"camera\": {\"track\": ...} and\n"
    "  movers[i].track set to that file replays them bit for bit (docs/tracks.md).";
}  // namespace

int cmdBake(const Args& args) {
  const auto a = parseArgs(args, {}, {"--out"}, kBakeUsage);
  if (a.positional.size() != 1 || a.value("--out").empty())
    throw UsageError(std::string("usage: ") + kBakeUsage);
  const auto loaded = cases::loadCase(a.positional[0]);
  const auto& spec = loaded.spec;
  // No paths in the file: a baked track is committed and must not depend on checkouts.
  const std::string description =
      "baked by taa-harness bake from " + spec.file.filename().string() + ": " +
      std::to_string(spec.script.frames) + " frames at " + std::to_string(spec.script.fps) + " fps";
  const std::string text = bakeCaseTrack(spec, description);

  const fs::path out = a.value("--out");
  if (out.has_parent_path()) createOutputDirectory(out.parent_path());
  writeFileAtomically(out, text);  // a reader never sees half a track
  std::cout << "wrote " << out.string() << ": camera and " << spec.movers.size() << " mover(s), "
            << spec.script.frames << " frames at " << spec.script.fps << " fps\n"
            << "replay: set \"camera\": {\"track\": \"<path relative to the case>\"} and each "
               "movers[i].track to it, keep script.fps and the jitter (docs/tracks.md)\n";
  return kPass;
}

}  // namespace taa::cli
