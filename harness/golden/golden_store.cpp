#include "golden/golden_store.h"

#include <fcntl.h>
#include <nlohmann/json.hpp>
#include <sys/file.h>
#include <stdio.h>
#include <unistd.h>

#include <signal.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/image_io.h"
#include "core/output_file.h"

namespace taa::golden {

namespace fs = std::filesystem;

std::optional<GoldenSet> loadGoldens(const fs::path& root, const std::string& caseName) {
  const fs::path dir = root / caseName;
  std::error_code ec;
  if (!fs::is_directory(dir, ec) || fs::is_empty(dir, ec)) return std::nullopt;
  GoldenSet set{dir, readManifest(dir / "manifest.json"), {}};
  for (const auto& f : set.manifest.frames) {
    const fs::path file = dir / f.file;
    if (!fs::exists(file, ec))
      throw GoldenError(file.string() + ": missing (listed in manifest.json); " + restoreHint(dir));
    Image image;
    try {
      image = readExr(file);
    } catch (const ImageIoError& e) {
      throw GoldenError(std::string(e.what()) + "; " + restoreHint(dir));
    }
    const std::string sha = pixelSha256(image);
    if (sha != f.sha256)
      throw GoldenError(file.string() + ": pixels (sha256 " + sha.substr(0, 12) +
                        ") do not match manifest.json (" + f.sha256.substr(0, 12) +
                        "): the file was overwritten or corrupted; " + restoreHint(dir));
    set.images.emplace(f.frame, std::move(image));
  }
  return set;
}

GoldensLock::GoldensLock(const fs::path& root) {
  createOutputDirectory(root);
  fd_ = ::open(root.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw OutputError(root, std::string("cannot open the folder to lock it: ") + std::strerror(errno));
  int rc;
  do rc = ::flock(fd_, LOCK_EX);  // waits while another bless holds it
  while (rc != 0 && errno == EINTR);
  if (rc != 0) {
    const int err = errno;
    ::close(fd_);
    throw OutputError(root, std::string("cannot lock the folder: ") + std::strerror(err));
  }
}

GoldensLock::~GoldensLock() {
  ::close(fd_);  // releases the lock
}

namespace {

// Leftovers of a bless that was killed before its exchange: never part of a set. Called
// under the folder's lock, so no live bless of this case has one.
void removeStale(const fs::path& root, const std::string& caseName) {
  const std::string prefix = "." + caseName + ".bless-";
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec))
    if (it->path().filename().string().rfind(prefix, 0) == 0) fs::remove_all(it->path(), ec);
}

// The process id of a staging folder's name (".NAME.bless-PID"), or 0.
pid_t stagingPid(const std::string& name) {
  const size_t at = name.rfind(".bless-");
  if (name.empty() || name[0] != '.' || at == std::string::npos || at == 0) return 0;
  const std::string digits = name.substr(at + 7);
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
    return 0;
  return pid_t(std::stol(digits));
}

}  // namespace

void replaceManifest(const std::filesystem::path& root, const Manifest& manifest) {
  const auto dir = root / manifest.caseName;
  writeFileAtomically(dir / "manifest.json", manifest.toJson().dump(2) + "\n");
  syncDirectory(dir);
}

std::vector<std::string> removeStaleStaging(const fs::path& root) {
  std::vector<std::string> notes;
  std::error_code ec;
  for (fs::directory_iterator it(root, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    const pid_t pid = stagingPid(name);
    if (pid <= 0 || pid == ::getpid()) continue;
    // A live process (or one we may not signal) keeps its folder: it may be blessing now.
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::error_code rm;
    fs::remove_all(it->path(), rm);
    notes.push_back(rm ? "cannot remove " + it->path().string() + ", a bless staging folder left by process " +
                             std::to_string(pid) + " (" + rm.message() + "); delete it by hand"
                       : "removed " + it->path().string() + ", a bless staging folder left by process " +
                             std::to_string(pid) + ", which has ended (killed during a bless)");
  }
  return notes;
}

void replaceGoldens(const fs::path& root, const Manifest& manifest,
                    const std::vector<std::pair<GoldenFrame, Image>>& frames) {
  createOutputDirectory(root);
  if (::access(root.c_str(), W_OK) != 0)
    throw OutputError(root, std::string("the goldens folder is not writable (") + std::strerror(errno) +
                                "): bless writes the new set beside the old one and swaps them, so it "
                                "needs write access there; the goldens are unchanged");
  removeStale(root, manifest.caseName);
  const fs::path target = root / manifest.caseName;
  const fs::path staging = root / ("." + manifest.caseName + ".bless-" + std::to_string(getpid()));
  createOutputDirectory(staging);
  try {
    for (const auto& [frame, image] : frames) writeExr(staging / frame.file, image);
    writeFileAtomically(staging / "manifest.json", manifest.toJson().dump(2) + "\n");
    syncDirectory(staging);  // the new set's entries are on disk before it takes the name
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  std::error_code ec;
  if (fs::exists(fs::symlink_status(target, ec))) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0) {
      const std::string why = std::strerror(errno);
      fs::remove_all(staging);
      throw OutputError(target, "cannot swap in " + staging.string() + ": " + why);
    }
    syncDirectory(root);
    fs::remove_all(staging, ec);  // now holds the previous set
  } else {
    fs::rename(staging, target, ec);
    if (ec) {
      fs::remove_all(staging, ec);
      throw OutputError(target, "cannot move the new set into place: " + ec.message());
    }
    syncDirectory(root);
  }
}

}  // namespace taa::golden
