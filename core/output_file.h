// Writing outputs (images, reports, results, goldens) so that a failure is an environment
// error naming the file: a full disk, a read-only folder or an unwritable --out surfaces as
// OutputError (exit 3), never as a regression, and never leaves a truncated file under the
// real name.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/errors.h"

namespace taa {

// An output could not be written. what() names the file and the system's reason.
class OutputError : public EnvironmentError {
 public:
  OutputError(const std::filesystem::path& file, const std::string& why)
      : EnvironmentError("cannot write " + file.string() + ": " + why) {}
};

// An output path the user gave that no command writes to: something other than a regular
// file (a device such as /dev/full, a FIFO, a directory, a socket), a symbolic link (whose
// target would be written, or the link replaced), or one of the command's own inputs. Bad
// input, exit 2; what() names the path, what it is and the fix.
class OutputPathError : public InputError {
 public:
  using InputError::InputError;
};

// The one output-path rule: `file` is a new path or a regular file (not a link), and none of
// `inputs` (compared by the file they lead to, so "./v.json" and a link to v.json count).
// `what` names the option ("bake --out"). Throws OutputPathError. Every command checks its
// outputs with it before it starts; writeFileAtomically applies the type rule again at the
// rename, for the files a command names itself.
void checkOutputPath(const std::filesystem::path& file,
                     const std::vector<std::filesystem::path>& inputs, const std::string& what);

// Flushes a folder's entries to disk; throws OutputError when the system reports a
// failure, which is where a full disk shows for delayed allocation.
void syncDirectory(const std::filesystem::path& dir);

// How many hidden temporary names (".NAME.tmp-PID-N", N from 0) a write tries before it gives up.
inline constexpr int kMaxTemporaryNames = 1000;

// Writes `content` to a hidden temporary file in the same folder, created exclusively (a file or
// link already under that name is passed over, never written through), checks every write,
// flushes it to disk and renames it over `file`. Throws OutputError; `file` is then as it was.
// Throws OutputPathError (checkOutputPath's type rule) when `file` exists and is a device node,
// FIFO, socket or link, which a rename would replace with a regular file (a directory there
// makes the rename fail: OutputError).
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

// Creates `dir` and its parents; throws OutputError naming it.
void createOutputDirectory(const std::filesystem::path& dir);

}  // namespace taa
