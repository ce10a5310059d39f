#include <algorithm>
#include <cmath>
#include <filesystem>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "api/scene_loading.h"
#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/exit_codes.h"
#include "cli/options.h"
#include "core/errors.h"
#include "core/output_file.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kNewCaseUsage =
    "taa-harness new-case --scene cases/scenes/NAME.gltf --name NAME [--cases DIR] [--frames N]\n"
    "  writes DIR/NAME.json (default DIR: the cases/ folder holding the scene) with a camera that\n"
    "  frames the scene's bounds; then look at `taa-harness render` output and bless it.";

// The scene must live under the cases folder: case files may only reference assets
// inside their own folder tree (portable, and nothing else on disk is read).
fs::path relativeInside(const fs::path& scene, const fs::path& casesDir) {
  const fs::path rel = fs::relative(fs::weakly_canonical(scene), fs::weakly_canonical(casesDir));
  if (rel.empty() || *rel.begin() == "..")
    throw UsageError(scene.string() + " is not inside " + casesDir.string() +
                     "; move it under " + (casesDir / "scenes").string() + " (cases reference assets below them)");
  return rel;
}
}  // namespace

int cmdNewCase(const Args& args) {
  const auto a = parseArgs(args, {}, {"--scene", "--name", "--cases", "--frames"}, kNewCaseUsage);
  if (!a.values.count("--scene") || !a.values.count("--name") || !a.positional.empty())
    throw UsageError(std::string("usage: ") + kNewCaseUsage);
  const fs::path scenePath = a.value("--scene");
  const std::string name = a.value("--name");
  // Letters, digits, '-' and '_' only: no separator, dot, space or control character reaches a
  // file name, and the name is short enough for every file system's name limit.
  constexpr size_t kMaxName = 100;
  if (name.empty() || name.size() > kMaxName ||
      name.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_") !=
          std::string::npos)
    throw UsageError("--name (" + std::to_string(name.size()) + " bytes): use 1 to " +
                     std::to_string(kMaxName) +
                     " letters, digits, '-' and '_' (it becomes NAME.json and goldens/NAME)");
  fs::path casesDir = a.value("--cases");
  if (casesDir.empty()) {
    // Default: the nearest ancestor folder named "cases".
    for (fs::path p = fs::absolute(scenePath).parent_path(); !p.empty() && p != p.root_path(); p = p.parent_path())
      if (p.filename() == "cases") {
        casesDir = p;
        break;
      }
    if (casesDir.empty()) throw UsageError(scenePath.string() + " is not under a cases/ folder; pass --cases DIR");
  }
  int frames = 16;
  if (a.values.count("--frames")) frames = int(numberOption(a, "--frames", 1, 100000, true));
  const fs::path rel = relativeInside(scenePath, casesDir);
  const fs::path out = casesDir / (name + ".json");
  std::error_code ec;
  if (fs::exists(fs::symlink_status(out, ec))) throw UsageError(out.string() + " exists; choose another --name or delete it");

  // Posed at the default fps, speed and offset: what the case plays until a user changes them.
  const auto [lo, hi] = gltfPosedBounds(scenePath, frames, spec::TimingSpec{}.fps);
  if (!std::isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z))
    throw InputError(scenePath.string() + ": its posed bounds are not finite; check its transforms");
  const glm::vec3 centre = (lo + hi) * 0.5f;
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-3f);
  // Far enough that the bounding sphere fits the 60-degree vertical field of view,
  // seen from the front and a little above.
  const float distance = radius / std::sin(glm::radians(30.0f)) * 1.15f;
  const glm::vec3 position = centre + glm::normalize(glm::vec3(0.0f, 0.35f, 1.0f)) * distance;
  nlohmann::json j = {
      {"description", "Scene " + rel.string() + " framed by its bounds (written by taa-harness new-case)"},
      {"scene", {{"builtin", "none"}, {"gltf", rel.generic_string()}}},
      {"camera",
       {{"position", {position.x, position.y, position.z}},
        {"target", {centre.x, centre.y, centre.z}},
        {"near", std::max(radius * 0.01f, 1e-4f)},
        {"far", distance + radius * 4.0f}}},
      {"script", {{"frames", frames}}},
      {"output", {{"frames", {frames - 1}}}}};
  const std::string text = j.dump(2) + "\n";
  cases::parseCase(text, out);  // what we write must validate
  writeFileAtomically(out, text);
  std::cout << "wrote " << out.string() << "\nnext: taa-harness render " << out.string()
            << " --out out/preview   (look at the PNGs), then taa-harness bless " << out.string()
            << " --reason \"new scene\"\n";
  return kPass;
}

}  // namespace taa::cli
