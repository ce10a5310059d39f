// Writing outputs (images, reports, results, goldens) so that a failure is an environment
// error naming the file: a full disk, a read-only folder or an unwritable --out surfaces as
// OutputError (exit 3), never as a regression, and never leaves a truncated file under the
// real name.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

#include "core/errors.h"

namespace taa {

// An output could not be written. what() names the file and the system's reason.
class OutputError : public EnvironmentError {
 public:
  OutputError(const std::filesystem::path& file, const std::string& why)
      : EnvironmentError("cannot write " + file.string() + ": " + why) {}
};

// Flushes a folder's entries to disk; throws OutputError when the system reports a
// failure, which is where a full disk shows for delayed allocation.
void syncDirectory(const std::filesystem::path& dir);

// Writes `content` to a hidden temporary file in the same folder, checks every write,
// flushes it to disk and renames it over `file`. Throws OutputError; `file` is then as it was.
void writeFileAtomically(const std::filesystem::path& file, std::string_view content);

// Creates `dir` and its parents; throws OutputError naming it.
void createOutputDirectory(const std::filesystem::path& dir);

}  // namespace taa
