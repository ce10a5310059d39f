// goldens/NAME/manifest.json: what was blessed, from which case file and renderer,
// in which environment, when and why; with the history of earlier blesses.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "golden/environment.h"

namespace taa::golden {

struct GoldenFrame {
  int frame = 0;
  std::string file;    // relative to the golden folder, e.g. "frame_0015.exr"
  std::string sha256;  // pixelSha256 of the frame
  int width = 0;
  int height = 0;
};

struct BlessRecord {
  std::string date;    // YYYY-MM-DD (UTC)
  std::string commit;  // renderer commit, "-dirty" when the tree had local changes
  std::string reason;
};

struct Manifest {
  std::string caseName;
  std::string caseSha256;  // of the case file's bytes when blessed
  Environment environment;
  BlessRecord bless;
  std::vector<BlessRecord> history;  // earlier blesses, newest first
  std::vector<GoldenFrame> frames;

  nlohmann::json toJson() const;
  static Manifest fromJson(const nlohmann::json& j, const std::filesystem::path& where);
  const GoldenFrame* find(int frame) const;
};

// Throws std::runtime_error naming the file when it is missing or malformed.
Manifest readManifest(const std::filesystem::path& file);

}  // namespace taa::golden
