#include "golden/golden_store.h"

#include <fcntl.h>
#include <sys/file.h>
#include <stdio.h>
#include <unistd.h>

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

// Leftovers of a bless that was killed before its exchange: never part of a set.
void removeStale(const fs::path& root, const std::string& caseName) {
  const std::string prefix = "." + caseName + ".bless-";
  for (const auto& entry : fs::directory_iterator(root))
    if (entry.path().filename().string().rfind(prefix, 0) == 0) fs::remove_all(entry.path());
}

}  // namespace

void replaceGoldens(const fs::path& root, const Manifest& manifest,
                    const std::vector<std::pair<GoldenFrame, Image>>& frames) {
  createOutputDirectory(root);
  removeStale(root, manifest.caseName);
  const fs::path target = root / manifest.caseName;
  const fs::path staging = root / ("." + manifest.caseName + ".bless-" + std::to_string(getpid()));
  fs::create_directories(staging);
  try {
    for (const auto& [frame, image] : frames) writeExr(staging / frame.file, image);
    writeFileAtomically(staging / "manifest.json", manifest.toJson().dump(2) + "\n");
    syncDirectory(staging);  // the new set's entries are on disk before it takes the name
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  if (fs::exists(target)) {
    if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) != 0) {
      const std::string why = std::strerror(errno);
      fs::remove_all(staging);
      throw OutputError(target, "cannot swap in " + staging.string() + ": " + why);
    }
    syncDirectory(root);
    fs::remove_all(staging);  // now holds the previous set
  } else {
    fs::rename(staging, target);
    syncDirectory(root);
  }
}

}  // namespace taa::golden
