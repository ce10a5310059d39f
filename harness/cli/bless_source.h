// What a bless turns into goldens for one case: every frame's hash and signature, the checked
// frames' images, the environment they were rendered in and the run's verdict on them. It
// comes from a render here, or from the folder a run wrote elsewhere (`bless --from OUT`,
// a machine's CI artifact), which needs no Vulkan device and is untrusted input.
#pragma once

#include <filesystem>
#include <map>
#include <string>

#include "case/case_loader.h"
#include "core/image.h"
#include "golden/bless.h"
#include "golden/environment.h"
#include "run/results.h"
#include "run/run_folder.h"

namespace taa::cli {

struct BlessSource {
  golden::Environment environment;
  std::string commit;  // of the renderer that rendered the frames
  golden::FrameDigests digests;
  std::map<int, Image> stored;  // the case's checked frames (output.frames)
  run::CaseResult result;       // its invariants and frame comparisons, as that run saw them
};

// A run's output folder as `bless --from` reads it, through the folder's one reader
// (run/run_folder.h): inside the folder once links are resolved, a regular file, bounded.
class RunFolderSource {
 public:
  // Reads OUT/results.json; UsageError (exit 2) naming the file when it cannot be used.
  explicit RunFolderSource(std::filesystem::path folder);

  // The case's source, checked against the tree: UsageError (exit 2) with the reason when the
  // run lacks the case or one of its frames, was made from other case, scene, track or shader
  // bytes than `loaded` and this build's SPIR-V, or a stored image does not hash to what the
  // results claim (or its signature differs).
  BlessSource source(const cases::LoadedCase& loaded) const;

  const std::filesystem::path& folder() const { return folder_.root(); }
  const run::RunResults& results() const { return results_; }

 private:
  run::RunFolder folder_;
  run::RunResults results_;
};

}  // namespace taa::cli
