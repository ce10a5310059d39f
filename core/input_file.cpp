#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace taa {
namespace {

namespace fs = std::filesystem;

std::string kindOf(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::string mib(uint64_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

[[noreturn]] void refuse(const fs::path& file, const std::string& problem) {
  throw InputFileError(file.string() + ": " + problem);
}

// Closes the descriptor on every path out of readInto.
struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

template <class Container>
void readInto(const fs::path& file, uint64_t maxBytes, Container& out, LastLink last) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  const Fd f{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY |
                                      (last == LastLink::Refuse ? O_NOFOLLOW : 0))};
  if (f.fd < 0) {
    const int err = errno;
    if (err == ENOENT || err == ENOTDIR)  // ENOTDIR: a file where a folder of the path should be
      throw InputFileMissing(file.string() +
                             ": does not exist; check the path (relative paths start at the "
                             "case's folder)");
    // With O_NOFOLLOW, ELOOP is the last part being a link, or a loop in the folders before it.
    struct stat own {};
    if (err == ELOOP && last == LastLink::Refuse && ::lstat(file.c_str(), &own) == 0 &&
        S_ISLNK(own.st_mode))
      refuse(file, "is a symbolic link; give the file itself");
    if (err == ELOOP) refuse(file, "is a symbolic-link loop; point the link at a file");
    refuse(file,
           "cannot be opened (" + std::string(std::strerror(err)) + "); check its permissions");
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0)
    refuse(file, "cannot be examined (" + std::string(std::strerror(errno)) + ")");
  if (!S_ISREG(st.st_mode))
    refuse(file, "is " + kindOf(st.st_mode) + ", not a regular file; give the path of a file");
  if (uint64_t(st.st_size) > maxBytes)
    refuse(file, "is " + std::to_string(uint64_t(st.st_size)) + " bytes, over the limit of " +
                     mib(maxBytes) + " for this kind of input; see docs/trust.md");
  // Back to blocking reads: a regular file never blocks, and O_NONBLOCK has done its job.
  ::fcntl(f.fd, F_SETFL, ::fcntl(f.fd, F_GETFL) & ~O_NONBLOCK);
  out.resize(size_t(st.st_size));
  out.resize(readFully(reinterpret_cast<char*>(out.data()), out.size(),
                       [&](char* dst, size_t n) { return ::read(f.fd, dst, n); }, file));
}

}  // namespace

size_t readFully(char* buf, size_t size, const std::function<ssize_t(char*, size_t)>& readSome,
                 const fs::path& file) {
  size_t done = 0;
  while (done < size) {
    const ssize_t n = readSome(buf + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(file, "cannot be read (" + std::string(std::strerror(errno)) + ")");
    if (n == 0) break;  // shrank while being read: keep what was there
    done += size_t(n);
  }
  return done;
}

std::string refusalProblem(const InputFileError& e, const fs::path& file) {
  std::string problem = e.what();
  const std::string prefix = file.string() + ": ";  // refuse()'s form
  if (problem.rfind(prefix, 0) == 0) problem.erase(0, prefix.size());
  if (const size_t fix = problem.rfind("; "); fix != std::string::npos) problem.resize(fix);
  return problem;
}

fs::path followLinks(fs::path p) {
  std::error_code ec;
  for (int hop = 0; hop < 40; ++hop) {
    p = fs::weakly_canonical(p, ec);
    if (ec) return {};
    if (!fs::is_symlink(fs::symlink_status(p, ec))) return p;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) return {};
    p = (target.is_absolute() ? target : p.parent_path() / target).lexically_normal();
  }
  return {};
}

bool isInsideFolder(const fs::path& folder, const fs::path& p) {
  if (folder.empty()) return false;
  const fs::path rel = p.lexically_relative(folder);
  return !rel.empty() && !rel.is_absolute() && *rel.begin() != "..";
}

fs::path containedRealPath(const fs::path& root, const fs::path& file, const std::string& what) {
  std::error_code ec;
  const fs::path realRoot = fs::canonical(root.empty() ? fs::path(".") : root, ec);
  if (ec) refuse(root, "cannot be resolved (" + ec.message() + ")");
  // Where the path leads decides before whether anything is there: a refusal never tells
  // whether a file outside the folder exists, nor where a link points.
  const fs::path led = followLinks(fs::absolute(file, ec));
  if (led.empty())
    refuse(file, what +
                     " is a symbolic-link loop (or a link chain over 40 long); point the "
                     "link at a file");
  if (!isInsideFolder(realRoot, led))
    refuse(file, what + " leads outside '" + realRoot.string() +
                     "' (through '..' or a symbolic link); copy the file itself into that folder");
  if (!fs::exists(fs::symlink_status(led, ec)))
    refuse(file, what + " does not exist; check the path (relative to the case's folder)");
  return led;
}

std::vector<fs::path> inputFilesIn(const fs::path& dir, const std::string& extension,
                                   std::vector<std::string>& problems) {
  std::vector<fs::path> files;
  std::error_code ec;
  fs::directory_iterator it(dir, ec), end;
  if (ec) {
    problems.push_back(dir.string() + ": cannot list the folder (" + ec.message() + ")");
    return files;
  }
  for (; it != end; it.increment(ec)) {
    if (ec) {
      problems.push_back(dir.string() + ": cannot list the folder (" + ec.message() + ")");
      break;
    }
    if (it->path().extension() != extension) continue;
    try {
      const fs::path real = containedRealPath(dir, it->path(), "the file");
      std::error_code kind;
      if (fs::is_directory(real, kind)) continue;  // a folder named x.json is no case
      files.push_back(it->path());
    } catch (const InputFileError& e) {
      problems.push_back(e.what());
    }
  }
  std::sort(files.begin(), files.end());
  std::sort(problems.begin(), problems.end());
  return files;
}

std::string readInputFile(const fs::path& file, uint64_t maxBytes, LastLink last) {
  std::string out;
  readInto(file, maxBytes, out, last);
  return out;
}

std::vector<uint8_t> readInputBytes(const fs::path& file, uint64_t maxBytes) {
  std::vector<uint8_t> out;
  readInto(file, maxBytes, out, LastLink::Follow);
  return out;
}

}  // namespace taa
