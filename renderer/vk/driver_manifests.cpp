#include "vk/driver_manifests.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/input_file.h"
#include "core/json_guard.h"

namespace taa::vk {

namespace fs = std::filesystem;

namespace {

// An unset or empty variable takes the loader's default.
std::string envOr(const EnvLookup& env, const char* name, const std::string& fallback) {
  const char* v = env(name);
  return v && *v ? std::string(v) : fallback;
}

void addEach(std::vector<fs::path>& out, const std::string& list) {
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find(':', start), list.size());
    if (end > start) out.push_back(fs::path(list.substr(start, end - start)) / "vulkan" / "icd.d");
    start = end + 1;
  }
}

}  // namespace

std::vector<fs::path> driverManifestFolders(const EnvLookup& env) {
  const std::string home = envOr(env, "HOME", "");
  std::vector<fs::path> out;
  const std::string configHome =
      envOr(env, "XDG_CONFIG_HOME", home.empty() ? "" : home + "/.config");
  if (!configHome.empty()) addEach(out, configHome);
  addEach(out, envOr(env, "XDG_CONFIG_DIRS", "/etc/xdg"));
  addEach(out, "/etc");
  const std::string dataHome =
      envOr(env, "XDG_DATA_HOME", home.empty() ? "" : home + "/.local/share");
  if (!dataHome.empty()) addEach(out, dataHome);
  addEach(out, envOr(env, "XDG_DATA_DIRS", "/usr/local/share:/usr/share"));
  return out;
}

bool isLavapipeManifest(std::string_view text) {
  if (!jsonStructureProblem(text).empty()) return false;
  const auto j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("ICD") || !j["ICD"].is_object()) return false;
  const auto& icd = j["ICD"];
  if (!icd.contains("library_path") || !icd["library_path"].is_string()) return false;
  const std::string name = fs::path(icd["library_path"].get<std::string>()).filename().string();
  return name.rfind("libvulkan_lvp", 0) == 0;
}

std::string lavapipeOnlyDriverFiles(const EnvLookup& env) {
  for (const char* chosen : {"VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"})
    if (const char* v = env(chosen); v && *v) return "";
  std::string out;
  for (const fs::path& folder : driverManifestFolders(env)) {
    std::error_code ec;
    fs::directory_iterator it(folder, ec), end;
    std::vector<fs::path> manifests;
    for (int seen = 0; !ec && it != end && seen < kMaxManifestsPerFolder; it.increment(ec), ++seen)
      if (it->path().extension() == ".json") manifests.push_back(it->path());
    std::sort(manifests.begin(), manifests.end());  // the loader's order within a folder varies
    for (const fs::path& m : manifests) {
      if (m.string().find(':') != std::string::npos) continue;  // cannot be named in the list
      try {
        if (!isLavapipeManifest(readInputFile(m, kMaxManifestBytes))) continue;
      } catch (const InputFileError&) {
        continue;  // unreadable, too big, a FIFO or a device: the loader's to judge, not ours
      }
      out += (out.empty() ? "" : ":") + m.string();
    }
  }
  return out;
}

}  // namespace taa::vk
