#include <cstdint>
#include <filesystem>
#include <iostream>

#include "api/tracks.h"
#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/errors.h"
#include "core/output_file.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
// Poses a bake writes (frames x (camera + movers)): each costs about 0.5 KB of memory while it
// is baked, written and replayed to check it, and its text must stay under the track reader's
// limit (kMaxTrackFileBytes) for the case to read it back (docs/trust.md).
constexpr uint64_t kMaxBakedPoses = 500000;

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
  const fs::path out = a.value("--out");
  checkOutputPath(out, {}, "bake --out");  // before the case is loaded and baked
  const auto loaded = cases::loadCase(a.positional[0]);
  const auto& spec = loaded.spec;
  // The case and the files it names: `bake v.json --out v.json` would replace the case, and
  // --out its own camera track the track it replays.
  const fs::path dir = spec.file.parent_path();
  std::vector<fs::path> inputs{spec.file};
  for (const std::string* ref : {&spec.camera.track, &spec.scene.gltf})
    if (!ref->empty()) inputs.push_back(dir / *ref);
  for (const auto& m : spec.movers)
    for (const std::string* ref : {&m.track, &m.gltf})
      if (!ref->empty()) inputs.push_back(dir / *ref);
  checkOutputPath(out, inputs, "bake --out");
  const uint64_t poses = uint64_t(spec.script.frames) * (1 + spec.movers.size());
  if (poses > kMaxBakedPoses)
    throw InputError(spec.file.string() + ": script.frames (" + std::to_string(spec.script.frames) +
                     ") x (the camera and " + std::to_string(spec.movers.size()) + " movers) is " +
                     std::to_string(poses) + " poses, over bake's limit of " +
                     std::to_string(kMaxBakedPoses) +
                     "; bake fewer frames or movers (docs/trust.md)");
  // No paths in the file: a baked track is committed and must not depend on checkouts.
  const std::string description =
      "baked by taa-harness bake from " + spec.file.filename().string() + ": " +
      std::to_string(spec.script.frames) + " frames at " + std::to_string(spec.script.fps) + " fps";
  const std::string text = bakeCaseTrack(spec, description);

  if (out.has_parent_path()) createOutputDirectory(out.parent_path());
  writeFileAtomically(out, text);  // a reader never sees half a track
  std::cout << "wrote " << out.string() << ": camera and " << spec.movers.size() << " mover(s), "
            << spec.script.frames << " frames at " << spec.script.fps << " fps\n"
            << "replay: set \"camera\": {\"track\": \"<path relative to the case>\"} and each "
               "movers[i].track to it, keep script.fps and the jitter (docs/tracks.md)\n";
  return kPass;
}

}  // namespace taa::cli
