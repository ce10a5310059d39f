#include "core/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace taa {
namespace {

namespace fs = std::filesystem;

void syncPath(const fs::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0)
    throw OutputError(path, std::string("cannot open it to flush: ") + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0)
    throw OutputError(path, std::string("flushing to disk failed: ") + std::strerror(err));
}

// What an existing non-regular path is, for messages; "" for a regular file or no file.
std::string notRegular(const fs::path& file) {
  struct stat st {};
  if (::lstat(file.c_str(), &st) != 0) return "";  // a new path
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISLNK(st.st_mode)) return "a symbolic link";
  if (S_ISDIR(st.st_mode)) return "a directory";
  if (S_ISFIFO(st.st_mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "a device";
  return "not a regular file";
}

[[noreturn]] void refuseType(const fs::path& file, const std::string& kind,
                             const std::string& what) {
  throw OutputPathError((what.empty() ? "" : what + " ") + file.string() + ": is " + kind +
                        "; outputs are written only to a new path or over a regular file, so "
                        "give another path");
}

}  // namespace

void checkOutputPath(const fs::path& file, const std::vector<fs::path>& inputs,
                     const std::string& what) {
  if (const std::string kind = notRegular(file); !kind.empty()) refuseType(file, kind, what);
  std::error_code ec;
  for (const auto& input : inputs) {
    if (input.empty()) continue;
    const bool same =
        fs::equivalent(file, input, ec) || fs::weakly_canonical(fs::absolute(file), ec) ==
                                               fs::weakly_canonical(fs::absolute(input), ec);
    if (same)
      throw OutputPathError(what + " " + file.string() + ": is the command's own input " +
                            input.string() +
                            "; writing it would replace what was read, so give "
                            "another path");
  }
}

void syncDirectory(const fs::path& dir) {
  syncPath(dir.empty() ? fs::path(".") : dir, O_RDONLY | O_DIRECTORY);
}

void writeFileAtomically(const fs::path& file, std::string_view content) {
  // Before anything is created beside it (as root, /dev/full's folder is writable). A folder
  // squatting on the name is left to the rename, whose failure is the environment's (exit 3).
  if (const std::string kind = notRegular(file); !kind.empty() && kind != "a directory")
    refuseType(file, kind, "");
  const fs::path dir = file.has_parent_path() ? file.parent_path() : fs::path(".");
  // The temporary name is created, never opened: O_EXCL | O_NOFOLLOW, so that a file or a link
  // someone put under a name we would pick (in a shared folder such as a cache) is passed over,
  // never written through. A name taken (a killed writer's, another thread's) tries the next.
  fs::path tmp;
  int fd = -1;
  int openErr = EEXIST;
  for (int n = 0; fd < 0 && openErr == EEXIST && n < kMaxTemporaryNames; ++n) {
    tmp = dir / ("." + file.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
                 std::to_string(n));
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    openErr = fd < 0 ? errno : 0;
  }
  if (fd < 0)
    throw OutputError(file, std::string("cannot create a file in ") + dir.string() + ": " +
                                (openErr == EEXIST ? "every temporary name is taken; delete "
                                                     "the hidden .tmp- files there"
                                                   : std::strerror(openErr)));
  auto fail = [&](const std::string& why) {
    std::error_code ignored;
    fs::remove(tmp, ignored);
    throw OutputError(file, why);
  };
  size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : ENOSPC;
      ::close(fd);
      fail(std::strerror(err));
    }
    done += size_t(n);
  }
  // Flushed before the rename, so a crash cannot leave the name pointing at lost data.
  const int synced = ::fsync(fd), syncErr = errno;
  const int closed = ::close(fd), closeErr = errno;
  if (synced != 0) fail(std::string("flushing to disk failed: ") + std::strerror(syncErr));
  if (closed != 0) fail(std::strerror(closeErr));
  struct stat st {};
  if (::stat(tmp.c_str(), &st) != 0 || uint64_t(st.st_size) != content.size())
    fail("the written file does not have the " + std::to_string(content.size()) + " bytes written");

  std::error_code ec;
  fs::rename(tmp, file, ec);
  if (ec) fail("cannot move the written file into place: " + ec.message());
}

void createOutputDirectory(const fs::path& dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw OutputPathError(dir.string() + ": is not a folder (" +
                          (notRegular(dir).empty() ? "a file" : notRegular(dir)) +
                          "); give the path of a folder, or a new one, to write outputs into");
  fs::create_directories(dir, ec);
  if (ec) throw OutputError(dir, "cannot create the folder: " + ec.message());
}

}  // namespace taa
