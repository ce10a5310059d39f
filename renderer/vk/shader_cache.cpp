#include "vk/shader_cache.h"

#include <sys/statvfs.h>
#include <unistd.h>

#include <cstdlib>
#include <string>

#include "core/cache_folder.h"

namespace taa::vk {

namespace fs = std::filesystem;

namespace {

fs::path wantedDir() {
  if (const char* env = std::getenv("TAA_SHADER_CACHE_DIR")) {
    const std::string v = env;
    return v == "off" ? fs::path() : fs::path(v);
  }
  return userCacheFolder("mesa");
}

}  // namespace

fs::path shaderCacheDir() {
  const fs::path dir = wantedDir();
  if (dir.empty()) return {};
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || ::access(dir.c_str(), W_OK | X_OK) != 0) return {};
  struct statvfs st {};
  if (::statvfs(dir.c_str(), &st) != 0) return {};
  if (uint64_t(st.f_bavail) * uint64_t(st.f_frsize) < kShaderCacheMinFreeBytes) return {};
  return dir;
}

}  // namespace taa::vk
