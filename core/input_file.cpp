#include "core/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

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
void readInto(const fs::path& file, uint64_t maxBytes, Container& out) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer forever.
  const Fd f{::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (f.fd < 0) {
    const int err = errno;
    if (err == ENOENT)
      refuse(file, "does not exist; check the path (relative paths start at the case's folder)");
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
  size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = ::read(f.fd, reinterpret_cast<char*>(out.data()) + done, out.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) refuse(file, "cannot be read (" + std::string(std::strerror(errno)) + ")");
    if (n == 0) break;  // shrank while being read: keep what was there
    done += size_t(n);
  }
  out.resize(done);
}

}  // namespace

fs::path containedRealPath(const fs::path& root, const fs::path& file, const std::string& what) {
  std::error_code ec;
  const fs::path realRoot = fs::canonical(root.empty() ? fs::path(".") : root, ec);
  if (ec) refuse(root, "cannot be resolved (" + ec.message() + ")");
  const fs::path real = fs::canonical(file, ec);
  if (ec) {
    if (fs::is_symlink(file, ec))
      refuse(file, what + " is a symbolic link to a missing file; point it at a file inside " +
                       realRoot.string());
    refuse(file, what + " does not exist; check the path (relative to the case's folder)");
  }
  const fs::path rel = real.lexically_relative(realRoot);
  if (rel.empty() || rel.is_absolute() || *rel.begin() == "..")
    refuse(file, what + " resolves to '" + real.string() + "', outside '" + realRoot.string() +
                     "' (through a symbolic link); copy the file itself into that folder");
  return real;
}

std::string readInputFile(const fs::path& file, uint64_t maxBytes) {
  std::string out;
  readInto(file, maxBytes, out);
  return out;
}

std::vector<uint8_t> readInputBytes(const fs::path& file, uint64_t maxBytes) {
  std::vector<uint8_t> out;
  readInto(file, maxBytes, out);
  return out;
}

}  // namespace taa
