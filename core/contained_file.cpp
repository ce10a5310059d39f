#include "core/contained_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

namespace taa {

namespace fs = std::filesystem;

fs::path checkContainedFile(const fs::path& folder, const fs::path& relative, uint64_t limit,
                            const std::string& what) {
  const fs::path file = folder / relative;
  std::error_code ec;
  if (!fs::is_directory(folder.empty() ? fs::path(".") : folder, ec))
    throw InputFileError(file.string() + ": " + what + " does not exist (" +
                         (folder.empty() ? fs::path(".") : folder).string() +
                         " is no folder); check the path");
  const fs::path real = containedRealPath(folder, file, what);
  struct stat st {};
  if (::lstat(real.c_str(), &st) != 0)
    throw InputFileError(file.string() + ": " + what + " cannot be examined (" +
                         std::strerror(errno) + ")");
  if (!S_ISREG(st.st_mode))
    throw InputFileError(file.string() + ": " + what + " is " +
                         (S_ISDIR(st.st_mode)                          ? "a directory"
                          : S_ISFIFO(st.st_mode)                       ? "a FIFO (named pipe)"
                          : S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode) ? "a device"
                                                                       : "not a regular file") +
                         ", not a regular file; the folder is not a run's output as taa-harness "
                         "writes it, so run the command again to make it");
  if (uint64_t(st.st_size) > limit)
    throw InputFileError(file.string() + ": " + what + " is " + std::to_string(st.st_size) +
                         " bytes, over the limit of " + std::to_string(limit >> 20) +
                         " MiB for it; see docs/trust.md");
  return real;
}

std::string readContainedFile(const fs::path& folder, const fs::path& relative, uint64_t limit,
                              const std::string& what) {
  const fs::path real = checkContainedFile(folder, relative, limit, what);
  return readInputFile(real, limit, LastLink::Refuse);
}

}  // namespace taa
