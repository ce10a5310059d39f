// The one way the harness reads a file an input names (a case, a track, a glTF scene and
// the buffers and images it refers to): a regular file of bounded size, opened once, and,
// when a root folder is given, found inside that folder after every symbolic link is
// resolved. A FIFO, device or directory is refused before a byte is read, so such a path
// can neither hang the harness nor feed it endless data. Messages name the file and never
// quote its content.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"

namespace taa {

// Size limits, documented in docs/trust.md.
inline constexpr uint64_t kMaxCaseFileBytes = uint64_t(4) << 20;     // 4 MiB
inline constexpr uint64_t kMaxTrackFileBytes = uint64_t(256) << 20;  // 256 MiB
inline constexpr uint64_t kMaxSceneFileBytes = uint64_t(1)
                                               << 30;  // 1 GiB (.gltf, .glb, .bin, images)

// Refusal of an input file. what() starts with the file's path and ends with the fix.
class InputFileError : public InputError {
 public:
  using InputError::InputError;
};
// The refusal of a file that is not there (open(2) said ENOENT or ENOTDIR), for callers to whom
// absence means something else than a broken file (a golden manifest not yet blessed).
class InputFileMissing : public InputFileError {
 public:
  using InputFileError::InputFileError;
};

// What a refusal of `file` says is wrong with it ("is a FIFO (named pipe), not a regular file"):
// its message without the path before and the fix for an input after, for callers with a fix
// of their own (a cache drops the entry; a missing build file wants a build).
std::string refusalProblem(const InputFileError& e, const std::filesystem::path& file);

// The real path of `file` (symbolic links resolved) after checking that it lies inside the
// real path of `root`. Throws InputFileError when it does not exist or leads outside; `what`
// says which input it is ("the case's scene.gltf") for the message.
std::filesystem::path containedRealPath(const std::filesystem::path& root,
                                        const std::filesystem::path& file, const std::string& what);

// Where `p` leads with every symbolic link followed, the last one too when it dangles (a
// link is judged by where it points, whether or not something is there); empty for a loop.
std::filesystem::path followLinks(std::filesystem::path p);

// Whether `p` lies inside `folder` by its text (both normalised and absolute).
bool isInsideFolder(const std::filesystem::path& folder, const std::filesystem::path& p);

// The files of `dir` (not its subfolders) ending in `extension`, sorted, each of which leads
// to something inside `dir` after resolving links (containedRealPath). An entry that leads
// out or loops, and a folder that cannot be listed, go to `problems` instead: the caller
// reports them (exit 2), and nothing of such a file is read.
std::vector<std::filesystem::path> inputFilesIn(const std::filesystem::path& dir,
                                                const std::string& extension,
                                                std::vector<std::string>& problems);

// Whether a symbolic link as the last part of a path is followed when the file is opened, or
// refused (a path already resolved, which a link put in its place since must not redirect).
enum class LastLink { Follow, Refuse };

// The whole content of `file`, which must be a regular file of at most `maxBytes` bytes.
// Throws InputFileError otherwise (missing, unreadable, FIFO, device, directory, too big).
std::string readInputFile(const std::filesystem::path& file, uint64_t maxBytes,
                          LastLink last = LastLink::Follow);
std::vector<uint8_t> readInputBytes(const std::filesystem::path& file, uint64_t maxBytes);

// Fills `buf` (`size` bytes) from `readSome(dst, n)`, a read(2) that may deliver fewer bytes than
// asked (NFS, FUSE) or fail with EINTR (asked again): the bytes read before the end, fewer than
// `size` for a file that shrank while being read. A read error is an InputFileError naming `file`.
size_t readFully(char* buf, size_t size, const std::function<ssize_t(char*, size_t)>& readSome,
                 const std::filesystem::path& file);

}  // namespace taa
