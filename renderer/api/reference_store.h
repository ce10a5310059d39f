// Reference frames kept on disk across runs, behind the in-run ReferenceCache: ctest's shards,
// a bisect's steps, a score after an edit of the resolve and the next run read a reference
// rendered by an earlier process instead of rendering it again. The key (a SHA-256, hex) names
// everything the reference read (harness/run/reference_key.h, ReferencePass::frameKey), so an
// entry is valid wherever its key is asked for.
//
// The folder is shared by processes running at once and may hold the remains of a killed one:
// an entry is written to a temporary file (a name starting with '.', never read as an entry),
// flushed and renamed into place; every read checks the entry's magic, key, shape and the
// SHA-256 of its pixels, and an entry failing any of them is deleted and rendered again.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>

#include "core/image.h"

namespace taa {

// An entry's bytes: magic, key, width, height, channels, SHA-256 of the pixels, the pixels
// (little-endian floats, as Image holds them).
std::string encodeReferenceEntry(const std::string& key, const Image& image);
// The image of a complete entry for `key`; nullopt for anything else (another key, a short or
// long file, a shape that does not fit the size, pixels whose SHA-256 differs).
std::optional<Image> decodeReferenceEntry(std::string_view bytes, const std::string& key);

inline constexpr uint64_t kDefaultReferenceCacheBytes = uint64_t(1) << 30;  // 1 GiB

class ReferenceStore {
 public:
  // `notes` receives one line for each problem that costs the cache but not the run (a folder
  // that cannot be written, a dropped entry).
  ReferenceStore(std::filesystem::path folder, uint64_t maxBytes, std::ostream& notes);

  // The store the environment names: $TAA_REFERENCE_CACHE_DIR, else the user's cache folder's
  // references/; its limit $TAA_REFERENCE_CACHE_MAX_MB (MiB), else 1 GiB. Null when neither
  // folder can be named. Throws InputError naming the variable for a limit that is
  // not a whole number of MiB.
  static std::unique_ptr<ReferenceStore> fromEnvironment(std::ostream& notes);

  // The verified entry under `key`, touched (its time is the least-recently-used order); a bad
  // entry is deleted and nullopt returned.
  std::optional<Image> load(const std::string& key);
  // Writes the entry atomically; a failure is a note (once), not an error.
  void save(const std::string& key, const Image& image);
  // Deletes the least recently used entries until the folder holds at most maxBytes of them,
  // and temporary files old enough that no live writer can own them.
  void trim();

  const std::filesystem::path& folder() const { return folder_; }
  uint64_t maxBytes() const { return maxBytes_; }

 private:
  void note(const std::string& line);
  // Sets `flag`; true the first time: a problem that would repeat for every reference is one note.
  bool firstTime(bool& flag);
  std::filesystem::path entryPath(const std::string& key) const;

  std::filesystem::path folder_;
  uint64_t maxBytes_;
  std::ostream& notes_;
  std::mutex mutex_;  // notes_ and the once-only flags
  bool writeFailed_ = false;
  bool dropFailed_ = false;
};

}  // namespace taa
