// goldens/NAME/manifest.json: what was blessed, from which case file and renderer,
// in which environment, when and why; with the history of earlier blesses.
#pragma once

#include <filesystem>
#include <nlohmann/json_fwd.hpp>
#include <optional>
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
// path relative to the working directory when it lies below it), or re-bless it.
std::string restoreHint(const std::filesystem::path& dir);
// The same for a damaged manifest.json, which a bless does not replace (it continues the
// manifest's history): restore it, or remove the folder to start the case's history over.
std::string manifestRestoreHint(const std::filesystem::path& dir);

// "frame_0015": a frame's file name less its extension, in a golden folder and in a run's
// folder alike (bless --from finds a run's frames by it).
std::string frameBase(int frame);

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

// What one environment renders for the case: its fingerprint's exact expectation. The primary
// positive is the manifest's own (environment, frames stored as EXR); every other environment
// blessed since (bless --add-environment) keeps only its hashes and signatures, since the exact
// path needs no image and the tolerance path compares with the primary's EXRs.
struct Positive {
  Environment environment;
  BlessRecord bless;
  std::vector<std::string> sequence;    // pixelSha256 of every rendered frame
  std::vector<std::string> signatures;  // golden::frameSignature of every rendered frame
};

struct Manifest {
  std::string caseName;
  std::string caseSha256;  // of the case file's bytes when blessed
  // "case_file": the case's folder and file name (golden/case_owner.h); empty in manifests
  // blessed before it was recorded.
  std::string caseFile;
  Environment environment;
  BlessRecord bless;
  std::vector<BlessRecord> history;  // earlier blesses, newest first
  std::vector<GoldenFrame> frames;   // the frames stored as EXR (the case's output.frames)
  // pixelSha256 of every rendered frame, index = frame number ("frame_sha256"): frames no EXR
  // covers are still checked bit for bit in the primary's environment.
  std::vector<std::string> sequence;
  // golden::frameSignature of every rendered frame ("frame_signatures"): what each frame looks
  // like, compared within tolerances in other environments, where the hashes differ.
  std::vector<std::string> signatures;
  // Positives of other environments ("other_environments"), in the order they were added. One
  // whose frames hash as the primary's is written as "same_frames_as_primary" (no second list).
  std::vector<Positive> others;

  // The primary positive, then the others.
  std::vector<Positive> positives() const;
  // The positive blessed in the environment of `fingerprint`, or nullopt.
  std::optional<Positive> positiveFor(const std::string& fingerprint) const;

  nlohmann::json toJson() const;
  static Manifest fromJson(const nlohmann::json& j, const std::filesystem::path& where);
  const GoldenFrame* find(int frame) const;
};

// Throws GoldenError naming the file and the fix when it is missing or malformed.
Manifest readManifest(const std::filesystem::path& file);

}  // namespace taa::golden
