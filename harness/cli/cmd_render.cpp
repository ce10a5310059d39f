#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "api/renderer.h"
#include "case/case_loader.h"
#include "cli/commands.h"
#include "cli/options.h"
#include "cli/batch_args.h"
#include "cli/run_support.h"
#include "core/image_io.h"
#include "core/output_file.h"
#include "run/run_folder.h"

namespace taa::cli {

namespace fs = std::filesystem;

namespace {
const char* kRenderUsage =
    "taa-harness render CASE --out DIR [--reference] [--device NAME] [--validate]\n"
    "  writes DIR/CASE/frame_NNNN.exr (linear half float) and .png (tonemapped sRGB) for each\n"
    "  frame in output.frames, aux buffers from output.aux, records.json and run.log;\n"
    "  --reference also writes frame_NNNN.reference.exr/.png, the supersampled ground truth";

}  // namespace

int cmdRender(const Args& args) {
  const auto a = parseArgs(args, {"--validate", "--reference"}, {"--out", "--device"}, kRenderUsage);
  if (a.positional.size() != 1 || !a.values.count("--out")) throw UsageError(std::string("usage: ") + kRenderUsage);
  const auto loaded = cases::loadCase(a.positional[0]);
  const auto& spec = loaded.spec;
  refuseOutputInGoldens(a.value("--out"), run::defaultGoldensRoot(spec.file));
  const fs::path dir = run::RunFolder(a.value("--out")).caseFolder(spec.name);
  createOutputDirectory(dir);

  RenderOptions options;
  if (a.has("--reference")) options.captures = {Capture::Reference};
  RunContext run(spec, a.value("--device"), a.has("--validate"), options);
  std::string log;
  for (const auto& line : run.renderer().log()) {
    log += line + "\n";
    std::cerr << spec.name << ": " << line << "\n";
  }
  writeFileAtomically(dir / "run.log", log);
  auto records = nlohmann::json::array();
  renderSequence(run.renderer(), spec, [&](FrameRecord& r) {
    nlohmann::json j = {{"frame", r.frame}, {"render_size", {r.renderSize.x, r.renderSize.y}},
                        {"camera_cut", r.cameraCut}, {"history_reset", r.historyReset}};
    for (const auto& [pass, ms] : r.gpuMs) j["gpu_ms"][pass] = ms;
    for (const auto& [name, value] : r.stats) j["stats"][name] = value;
    if (r.hasImages) {
      const int f = r.frame;
      writeExr(dir / run::frameFileName(f, run::FrameFile::Exr), r.color);
      writePng(dir / run::frameFileName(f, run::FrameFile::Png), r.color);
      // Depth, ids and velocities lose meaning in half floats; the colour buffers do not.
      for (const auto& aux : r.aux) {
        const bool exact = aux.name == "depth" || aux.name == "material_id" || aux.name == "velocity";
        (exact ? writeExrFloat : writeExr)(dir / run::frameCaptureName(f, aux.name), aux.image);
      }
      if (r.hasReference) {
        writeExrFloat(dir / run::frameFileName(f, run::FrameFile::ReferenceExr), r.reference);
        writePng(dir / run::frameFileName(f, run::FrameFile::ReferencePng), r.reference);
      }
      j["sha256"] = r.colorSha256;
      std::cout << spec.name << " frame " << r.frame << " sha256 " << r.colorSha256 << "\n";
    }
    records.push_back(std::move(j));
  }, run.progress());
  writeFileAtomically(dir / "records.json", records.dump(1) + "\n");
  return run.finish();
}

}  // namespace taa::cli
