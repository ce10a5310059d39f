#include "run/build_identity.h"

#include <elf.h>
#include <link.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <vector>

#include "api/device.h"
#include "core/input_file.h"
#include "core/sha256.h"
#include "golden/environment.h"

namespace taa::run {

namespace {

namespace fs = std::filesystem;

// The NT_GNU_BUILD_ID note of the main program (the first object dl_iterate_phdr reports).
int readBuildId(dl_phdr_info* info, size_t, void* out) {
  auto& id = *static_cast<std::string*>(out);
  for (int i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type != PT_NOTE) continue;
    const auto* p = reinterpret_cast<const uint8_t*>(info->dlpi_addr + ph.p_vaddr);
    const uint8_t* end = p + ph.p_memsz;
    auto align4 = [](size_t n) { return (n + 3) & ~size_t(3); };
    while (p + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, p, sizeof(note));
      const uint8_t* name = p + sizeof(note);
      const uint8_t* desc = name + align4(note.n_namesz);
      if (desc + note.n_descsz > end) break;
      if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 &&
          std::memcmp(name, "GNU", 4) == 0) {
        id = "build-id " + toHex(desc, note.n_descsz);
        return 1;
      }
      p = desc + align4(note.n_descsz);
    }
  }
  return 1;  // only the main program is looked at
}

// Bounded (the program itself, without a build id, is the largest file hashed), and never
// waiting on a FIFO put where a file was: a file that cannot be read counts as its refusal, so
// the identity still differs from the build's.
void hashFile(Sha256& h, const fs::path& path) {
  constexpr uint64_t kMaxHashedBytes = uint64_t(1) << 30;
  std::string bytes;
  try {
    bytes = readInputFile(path, kMaxHashedBytes);
  } catch (const InputFileError& e) {
    bytes = std::string("unreadable: ") + e.what();
  }
  h.update(bytes.data(), bytes.size());
}

std::string hexOf(Sha256& h) {
  const auto d = h.finish();
  return toHex(d.data(), d.size());
}

// Names and bytes of the files, in name order.
std::string digestOf(std::vector<fs::path> files) {
  std::sort(files.begin(), files.end());
  Sha256 h;
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    const uint64_t n = name.size();
    h.update(&n, sizeof(n));  // lengths delimit the parts
    h.update(name.data(), name.size());
    hashFile(h, f);
  }
  return hexOf(h);
}

}  // namespace

std::string executableIdentity() {
  static const std::string identity = [] {
    std::string id;
    dl_iterate_phdr(readBuildId, &id);
    if (!id.empty()) return id;
    Sha256 h;
    hashFile(h, "/proc/self/exe");
    return "sha256 " + hexOf(h);
  }();
  return identity;
}

std::string spirvIdentity() {
  std::vector<fs::path> files;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(shaderFolder(), ec))
    if (e.path().extension() == ".spv") files.push_back(e.path());
  return digestOf(std::move(files));
}

std::string buildIdentity(const std::string& deviceRequest, bool missingGoldenFails,
                          bool requireExact) {
  std::string device = deviceRequest;
  if (device.empty())
    if (const char* env = std::getenv("TAA_DEVICE")) device = env;
  return executableIdentity() + " | spirv " + spirvIdentity() + " | " + golden::cpuFeatureLevel() +
         " | device " + (device.empty() ? "default" : device) +
         (missingGoldenFails ? " | missing goldens fail" : " | missing goldens skip") +
         (requireExact ? " | exact required" : "");
}

std::string folderDigest(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return "none";
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_regular_file(ec)) files.push_back(e.path());
  return digestOf(files);
}

}  // namespace taa::run
