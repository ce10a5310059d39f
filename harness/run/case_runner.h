// Runs one case end to end: render (and the reference when its checks need one),
// feed the invariants, compare checked frames with goldens, write the images the
// report shows. Never throws for a failed check; throws for bad input or a broken
// environment.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <string>

#include "api/device.h"
#include "case/case_loader.h"
#include "core/image.h"
#include "api/reference_cache.h"
#include "run/results.h"

namespace taa::run {

struct RunOptions {
  std::filesystem::path outDir;       // case outputs go to outDir/NAME/
  std::filesystem::path goldensRoot;  // empty: the folder goldens/ beside the case's folder
  bool writeImages = true;            // PNG/EXR of checked frames, diffs and crops
  // A case without goldens fails (CI, where it means a golden was never committed) instead
  // of being a skip (a new case on a developer's machine).
  bool missingGoldenFails = false;
  // A case whose goldens hold no positive for this environment fails instead of passing on the
  // tolerance path (`run --require-exact`, TAA_REQUIRE_EXACT=1).
  bool requireExact = false;
  // Called before each frame with (frame, frame count); for terminal progress.
  std::function<void(int, int)> progress;
  // Reference frames shared by the run's cases (and the frames of a still scene); null:
  // every reference is rendered.
  ReferenceCache* references = nullptr;
};

// Where a case's goldens live: goldens/ next to the folder holding the case file.
std::filesystem::path defaultGoldensRoot(const std::filesystem::path& caseFile);

// The case's golden folder under `goldensRoot` (empty: the default) as a run reads it,
// digested (run::folderDigest); "" when the case checks no goldens. A verdict taken from an
// earlier run (--verdict-from) needs the same goldens as well as the same inputs and build.
std::string goldensDigest(const spec::CheckedCase& spec, const std::filesystem::path& goldensRoot);

// `outputs`, when given, receives the checked frames' images (bless writes them).
CaseResult runCase(Device& device, const cases::LoadedCase& loaded, const RunOptions& options,
                   std::map<int, Image>* outputs = nullptr);

}  // namespace taa::run
