#include "api/reference_store.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <system_error>
#include <vector>

#include "core/cache_folder.h"
#include "core/errors.h"
#include "core/input_file.h"
#include "core/output_file.h"
#include "core/sha256.h"

namespace taa {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'T', 'A', 'A', 'R', 'E', 'F', '1', '\n'};
constexpr size_t kDigestBytes = 32;
constexpr int kMaxSide = 1 << 15;
// An entry is its header and at most kMaxSide^2 RGBA floats; anything larger is not one.
constexpr uint64_t kMaxEntryBytes = uint64_t(kMaxSide) * kMaxSide * 16 + 4096;
// A temporary file this old belongs to a writer that was killed: writing one entry takes
// well under a second.
constexpr auto kStaleTemp = std::chrono::minutes(10);

void putU32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out += char((v >> (8 * i)) & 0xff);
}

uint32_t getU32(std::string_view b, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(b[at + size_t(i)])) << (8 * i);
  return v;
}

// Keys are what ReferencePass::frameKey gives: 64 lowercase hex digits, safe as a file name.
bool validKey(const std::string& key) {
  return key.size() == 64 && std::all_of(key.begin(), key.end(), [](char c) {
           return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
         });
}

bool isTempName(const std::string& name) {
  return !name.empty() && name[0] == '.' && name.find(".tmp-") != std::string::npos;
}

}  // namespace

std::string encodeReferenceEntry(const std::string& key, const Image& image) {
  const size_t payload = image.data.size() * sizeof(float);
  std::string out(kMagic, sizeof(kMagic));
  putU32(out, uint32_t(key.size()));
  out += key;
  putU32(out, uint32_t(image.width));
  putU32(out, uint32_t(image.height));
  putU32(out, uint32_t(image.channels));
  Sha256 h;
  h.update(image.data.data(), payload);
  const auto digest = h.finish();
  out.append(reinterpret_cast<const char*>(digest.data()), digest.size());
  out.append(reinterpret_cast<const char*>(image.data.data()), payload);
  return out;
}

std::optional<Image> decodeReferenceEntry(std::string_view b, const std::string& key) {
  size_t at = sizeof(kMagic);
  if (b.size() < at + 4 || std::memcmp(b.data(), kMagic, sizeof(kMagic)) != 0) return std::nullopt;
  const uint64_t keyLen = getU32(b, at);
  at += 4;
  if (keyLen != key.size() || b.size() - at < keyLen + 12 + kDigestBytes) return std::nullopt;
  if (b.substr(at, keyLen) != key) return std::nullopt;
  at += keyLen;
  const uint32_t w = getU32(b, at), h = getU32(b, at + 4), c = getU32(b, at + 8);
  at += 12;
  if (w == 0 || h == 0 || c == 0 || w > kMaxSide || h > kMaxSide || c > 4) return std::nullopt;
  const uint64_t payload = uint64_t(w) * h * c * sizeof(float);
  const std::string_view digest = b.substr(at, kDigestBytes);
  at += kDigestBytes;
  if (b.size() - at != payload) return std::nullopt;
  Sha256 sha;
  sha.update(b.data() + at, payload);
  const auto actual = sha.finish();
  if (std::memcmp(actual.data(), digest.data(), kDigestBytes) != 0) return std::nullopt;
  Image image{static_cast<int>(w), static_cast<int>(h), static_cast<int>(c)};
  std::memcpy(image.data.data(), b.data() + at, payload);
  return image;
}

ReferenceStore::ReferenceStore(fs::path folder, uint64_t maxBytes, std::ostream& notes)
    : folder_(std::move(folder)), maxBytes_(maxBytes), notes_(notes) {}

std::unique_ptr<ReferenceStore> ReferenceStore::fromEnvironment(std::ostream& notes) {
  fs::path folder;
  if (const char* env = std::getenv("TAA_REFERENCE_CACHE_DIR"); env && *env)
    folder = env;
  else
    folder = userCacheFolder("references");
  if (folder.empty()) return nullptr;
  uint64_t maxBytes = kDefaultReferenceCacheBytes;
  if (const char* env = std::getenv("TAA_REFERENCE_CACHE_MAX_MB"); env && *env) {
    char* end = nullptr;
    errno = 0;
    const unsigned long long mb = std::strtoull(env, &end, 10);
    if (*end != '\0' || errno != 0 || env[0] == '-' || mb > (uint64_t(1) << 40))
      throw InputError(std::string("TAA_REFERENCE_CACHE_MAX_MB='") + env +
                       "': expected the reference cache's size limit in MiB, a whole "
                       "number (0 keeps no entry); unset it for 1024");
    maxBytes = uint64_t(mb) << 20;
  }
  return std::make_unique<ReferenceStore>(folder, maxBytes, notes);
}

void ReferenceStore::note(const std::string& line) {
  std::lock_guard<std::mutex> lock(mutex_);
  notes_ << "note: reference cache " << folder_.string() << ": " << line << "\n";
}

fs::path ReferenceStore::entryPath(const std::string& key) const {
  return folder_ / (key + ".ref");
}

std::optional<Image> ReferenceStore::load(const std::string& key) {
  if (!validKey(key)) return std::nullopt;
  const fs::path path = entryPath(key);
  std::string bytes;
  std::string problem = "torn, truncated or altered: it failed its check";
  try {
    // The one hardened reader: the cache folder may be shared or restored from elsewhere, and a
    // FIFO, device or link under an entry's name must neither hang the run nor lead outside.
    bytes = readInputFile(path, kMaxEntryBytes, LastLink::Refuse);
  } catch (const InputFileMissing&) {
    return std::nullopt;
  } catch (const InputFileError& e) {
    problem = refusalProblem(e, path);  // the note names the file; the fix is the drop
  }
  if (std::optional<Image> image = decodeReferenceEntry(bytes, key)) {  // "" decodes to none
    // Recently used: trim() keeps it over entries not read since. The entry itself, never
    // where a link put in its place since would lead.
    ::utimensat(AT_FDCWD, path.c_str(), nullptr, AT_SYMLINK_NOFOLLOW);
    return image;
  }
  std::error_code ec;
  if (fs::remove(path, ec)) {  // a link goes, not what it points at
    note("dropped " + path.filename().string() + " (" + problem +
         "); the reference is rendered again");
  } else if (ec && firstTime(dropFailed_)) {
    // A folder that cannot be searched, or a folder under an entry's name: once, not per frame.
    note("cannot drop " + path.filename().string() + " (" + problem + "; " + ec.message() +
         "); such entries are rendered again");
  }
  return std::nullopt;
}

bool ReferenceStore::firstTime(bool& flag) {
  std::lock_guard<std::mutex> lock(mutex_);
  const bool first = !flag;
  flag = true;
  return first;
}

void ReferenceStore::save(const std::string& key, const Image& image) {
  if (!validKey(key) || image.data.empty()) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (writeFailed_) return;
  }
  try {
    createOutputDirectory(folder_);
    writeFileAtomically(entryPath(key), encodeReferenceEntry(key, image));
  } catch (const std::exception& e) {
    // A folder in the entry's place (load could not drop it) costs that entry, not the cache.
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(entryPath(key), ec))) {
      note("not written " + entryPath(key).filename().string() +
           ": a folder is in its place; remove it to keep this reference");
      return;
    }
    if (firstTime(writeFailed_))
      note(std::string("not written (") + e.what() +
           "); this run renders its references as without the cache. Set "
           "TAA_REFERENCE_CACHE_DIR to a writable folder to keep them");
  }
}

void ReferenceStore::trim() {
  struct Entry {
    fs::path path;
    fs::file_time_type time;
    uintmax_t size;
  };
  std::vector<Entry> entries;
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (fs::directory_iterator it(folder_, ec), end; !ec && it != end; it.increment(ec)) {
    std::error_code e2;
    const std::string name = it->path().filename().string();
    // Only files the store wrote count: a link would count (and date) what it points at.
    if (!it->is_regular_file(e2) || it->is_symlink(e2)) continue;
    const auto time = it->last_write_time(e2);
    if (e2) continue;
    if (isTempName(name)) {
      if (now - time > kStaleTemp) fs::remove(it->path(), e2);
      continue;
    }
    if (it->path().extension() != ".ref") continue;
    const auto size = it->file_size(e2);
    if (!e2) entries.push_back({it->path(), time, size});
  }
  // Newest first; the name breaks ties so two trims at once agree.
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.time != b.time ? a.time > b.time : a.path < b.path;
  });
  uint64_t kept = 0;
  bool full = false;  // every entry older than the first that does not fit goes too
  for (const auto& e : entries) {
    full = full || kept + e.size > maxBytes_;
    if (!full) {
      kept += e.size;
      continue;
    }
    std::error_code e2;
    fs::remove(e.path, e2);
  }
}

}  // namespace taa
