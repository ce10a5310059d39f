#include "run/results_seal.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>

#include "core/cache_folder.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "core/sha256.h"

namespace taa::run {

namespace {

namespace fs = std::filesystem;

constexpr size_t kKeyBytes = 32;

struct Fd {
  int fd;
  ~Fd() {
    if (fd >= 0) ::close(fd);
  }
};

// The key file's content, or "" with `why` set: a file that others could read or write, or
// that is not a plain file of the user's, keys nothing.
std::string readKey(const fs::path& file, std::string& why) {
  const Fd f{::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC)};
  if (f.fd < 0) {
    why = file.string() + ": cannot be opened (" + std::strerror(errno) + ")";
    return {};
  }
  struct stat st {};
  if (::fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid() ||
      (st.st_mode & 077) != 0 || st.st_size != off_t(kKeyBytes)) {
    why = file.string() + ": not a " + std::to_string(kKeyBytes) +
          "-byte file of this user with mode 0600; remove it (a new key is made on next use)";
    return {};
  }
  std::string key(kKeyBytes, '\0');
  if (::read(f.fd, key.data(), key.size()) != ssize_t(key.size())) {
    why = file.string() + ": cannot be read";
    return {};
  }
  return key;
}

// A fresh key, published under `file` only if none is there: two runs starting at once (ctest's
// shards) agree on the first one written.
void makeKey(const fs::path& file) {
  std::array<char, kKeyBytes> key{};
  size_t got = 0;
  while (got < key.size()) {
    const ssize_t n = ::getrandom(key.data() + got, key.size() - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    got += size_t(n);
  }
  static std::atomic<unsigned> counter{0};
  const fs::path tmp =
      file.string() + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  const Fd f{::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0600)};
  if (f.fd < 0) return;
  const bool written =
      ::write(f.fd, key.data(), key.size()) == ssize_t(key.size()) && ::fsync(f.fd) == 0;
  if (written) (void)::link(tmp.c_str(), file.c_str());  // EEXIST: another run's key stands
  ::unlink(tmp.c_str());
}

// This user's key, made on first use; "" with `why` set when there is none to use.
std::string userKey(std::string& why) {
  const fs::path file = userCacheFolder("results-seal.key");
  if (file.empty()) {
    why = "neither $XDG_CACHE_HOME nor $HOME is set, so there is no key to seal results with";
    return {};
  }
  std::error_code ec;
  fs::create_directories(file.parent_path(), ec);
  if (!fs::exists(fs::symlink_status(file, ec))) makeKey(file);
  return readKey(file, why);
}

}  // namespace

fs::path sealPathOf(const fs::path& results) {
  return fs::path(results.string() + ".seal");
}

std::string hmacSha256Hex(std::string_view key, std::string_view message) {
  constexpr size_t kBlock = 64;
  std::array<uint8_t, kBlock> k{};
  if (key.size() > kBlock) {
    Sha256 h;
    h.update(key.data(), key.size());
    const auto d = h.finish();
    std::memcpy(k.data(), d.data(), d.size());
  } else {
    std::memcpy(k.data(), key.data(), key.size());
  }
  std::array<uint8_t, kBlock> pad{};
  for (size_t i = 0; i < kBlock; ++i) pad[i] = k[i] ^ 0x36;
  Sha256 inner;
  inner.update(pad.data(), pad.size());
  inner.update(message.data(), message.size());
  const auto innerDigest = inner.finish();
  for (size_t i = 0; i < kBlock; ++i) pad[i] = k[i] ^ 0x5c;
  Sha256 outer;
  outer.update(pad.data(), pad.size());
  outer.update(innerDigest.data(), innerDigest.size());
  const auto d = outer.finish();
  return toHex(d.data(), d.size());
}

void writeUnsealedResults(const fs::path& results, const std::string& text) {
  const fs::path seal = sealPathOf(results);
  std::error_code ec;
  fs::remove(seal, ec);
  if (ec) throw OutputError(seal, "cannot remove the old seal: " + ec.message());
  writeFileAtomically(results, text);
}

std::string writeSealedResults(const fs::path& results, const std::string& text) {
  writeUnsealedResults(results, text);
  const fs::path seal = sealPathOf(results);
  std::string why;
  const std::string key = userKey(why);
  if (key.empty()) return why;
  writeFileAtomically(seal, hmacSha256Hex(key, text) + "\n");
  return "";
}

std::string sealProblem(const fs::path& results, const std::string& text) {
  const fs::path seal = sealPathOf(results);
  std::string stored;
  try {
    stored = readInputFile(seal, 1024);
  } catch (const InputFileError& e) {
    return e.what();
  }
  std::string why;
  const std::string key = userKey(why);
  if (key.empty()) return why;
  if (stored != hmacSha256Hex(key, text) + "\n")
    return seal.string() + " does not match the bytes of " + results.string() +
           " (edited since, or sealed by another user)";
  return "";
}

}  // namespace taa::run
