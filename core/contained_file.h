// The one way a command reads a file out of another run's folder (a shard's results.json and
// its frame images for `merge`, `coverage --results`, `run --verdict-from`, `bless --from`):
// the folder is the user's choice, but every path inside it came from that run's files and may
// have been forged or replaced by a link. A file is read only when it lies inside the folder
// after every symbolic link is resolved, is a regular file (never a FIFO, device or directory,
// so it can neither hang the command nor feed it endless data) and is at most `limit` bytes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "core/input_file.h"

namespace taa {

// Bounds for the files of another run's folder (docs/trust.md).
inline constexpr uint64_t kMaxResultsFileBytes = uint64_t(256) << 20;  // a results.json, 256 MiB
inline constexpr uint64_t kMaxRunImageBytes = uint64_t(256) << 20;     // one frame PNG, 256 MiB

// The real path of `folder / relative` after checking it: inside the real path of `folder`,
// a regular file of at most `limit` bytes. `what` names it for messages ("shard 2's frame
// image"). Throws InputFileError (exit 2) naming the file, what is wrong and the fix; a
// refusal never says where a link outside points.
std::filesystem::path checkContainedFile(const std::filesystem::path& folder,
                                         const std::filesystem::path& relative, uint64_t limit,
                                         const std::string& what);

// The bytes of that file, read once after the checks (opened without following a link, so a
// link put in its place after the check is refused, not followed).
std::string readContainedFile(const std::filesystem::path& folder,
                              const std::filesystem::path& relative, uint64_t limit,
                              const std::string& what);

}  // namespace taa
