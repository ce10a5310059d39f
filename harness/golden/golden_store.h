// goldens/NAME/: the EXRs of a case's checked frames and their manifest. Replacing
// a case's goldens is atomic: a failed or killed bless leaves the old set whole.
#pragma once

#include <filesystem>
#include <optional>
#include <utility>
#include <vector>

#include "core/image.h"
#include "golden/manifest.h"

namespace taa::golden {

struct GoldenSet {
  std::filesystem::path dir;
  Manifest manifest;
  // Reads the frame's EXR; throws ImageIoError naming the file.
  Image load(const GoldenFrame& frame) const;
};

// The case's goldens, or nullopt when it has none yet.
std::optional<GoldenSet> loadGoldens(const std::filesystem::path& root, const std::string& caseName);

// Writes `frames` and `manifest` into a hidden sibling folder, then exchanges it with
// goldens/NAME in one rename (renameat2 RENAME_EXCHANGE), then deletes the old set.
// Any failure before the exchange removes the new folder and leaves the old set.
void replaceGoldens(const std::filesystem::path& root, const Manifest& manifest,
                    const std::vector<std::pair<GoldenFrame, Image>>& frames);

}  // namespace taa::golden
