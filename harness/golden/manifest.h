// goldens/NAME/manifest.json: what was blessed, from which case file and renderer,
// in which environment, when and why; with the history of earlier blesses.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "golden/environment.h"

namespace taa::golden {

// A golden set that cannot be trusted: a manifest that is missing or does not parse, an EXR
// that is missing or whose pixels do not match the manifest. The message names the file and
// how to restore it.
class GoldenError : public InputError {
 public:
  using InputError::InputError;
};

// "git checkout -- goldens/NAME": how to restore a case's golden folder `dir` from git (the
// path relative to the working directory when it lies below it).
std::string restoreHint(const std::filesystem::path& dir);

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
  std::vector<GoldenFrame> frames;   // the frames stored as EXR (the case's output.frames)
  // pixelSha256 of every rendered frame, index = frame number ("frame_sha256"): frames no EXR
  // covers are still checked bit for bit in the golden's environment.
  std::vector<std::string> sequence;
  // golden::frameSignature of every rendered frame ("frame_signatures"): what each frame looks
  // like, compared within tolerances in other environments, where the hashes differ.
  std::vector<std::string> signatures;

  nlohmann::json toJson() const;
  static Manifest fromJson(const nlohmann::json& j, const std::filesystem::path& where);
  const GoldenFrame* find(int frame) const;
};

// Throws GoldenError naming the file and the fix when it is missing or malformed.
Manifest readManifest(const std::filesystem::path& file);

}  // namespace taa::golden
