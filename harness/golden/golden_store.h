// goldens/NAME/: the EXRs of a case's checked frames and their manifest. Replacing
// a case's goldens is atomic: a failed or killed bless leaves the old set whole.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/image.h"
#include "golden/manifest.h"

namespace taa::golden {

struct GoldenSet {
  std::filesystem::path dir;
  Manifest manifest;
  std::map<int, Image> images;  // every frame of manifest.frames, verified against its hash
  const Image& load(const GoldenFrame& frame) const { return images.at(frame.frame); }
};

// The case's goldens, or nullopt when it has no folder (or an empty one) yet. Verified
// before use: a missing or unparsable manifest, a missing or unreadable EXR, or an EXR
// whose pixels do not hash to the manifest's sha256 throws GoldenError naming the file
// and how to restore it; an overwritten golden is never compared with.
std::optional<GoldenSet> loadGoldens(const std::filesystem::path& root, const std::string& caseName);

// An exclusive lock on a goldens folder (flock on the folder itself, so no lock file is
// left behind), held from reading the old manifest to the exchange: concurrent blesses of
// one folder run one after the other, and each sees the history the previous one wrote.
// Creates the folder. Throws OutputError when it cannot be created or locked.
class GoldensLock {
 public:
  explicit GoldensLock(const std::filesystem::path& root);
  ~GoldensLock();
  GoldensLock(const GoldensLock&) = delete;
  GoldensLock& operator=(const GoldensLock&) = delete;

 private:
  int fd_ = -1;
};

// Writes `frames` and `manifest` into a hidden sibling folder, flushes every file and the
// folder to disk, then exchanges it with goldens/NAME in one rename (renameat2
// RENAME_EXCHANGE), flushes the goldens folder and deletes the old set. Any failure before
// the exchange removes the new folder and leaves the old set. Hold a GoldensLock on `root`
// when another process may bless into it.
void replaceGoldens(const std::filesystem::path& root, const Manifest& manifest,
                    const std::vector<std::pair<GoldenFrame, Image>>& frames);

// Replaces goldens/NAME/manifest.json alone (atomically: a temporary file renamed over it), for a
// change that keeps every image, such as another environment's positive. Hold a GoldensLock.
void replaceManifest(const std::filesystem::path& root, const Manifest& manifest);

// Removes the staging folders (.NAME.bless-PID) that blesses killed before their exchange
// left in `root`, of processes that have ended; returns a line for each, to print. A live
// process's folder is kept. Run at the start of every run and bless.
std::vector<std::string> removeStaleStaging(const std::filesystem::path& root);

}  // namespace taa::golden
