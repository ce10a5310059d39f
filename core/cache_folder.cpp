#include "core/cache_folder.h"

#include <cstdlib>

namespace taa {

std::filesystem::path userCacheFolder(const std::string& sub) {
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    return std::filesystem::path(xdg) / "taa-harness" / sub;
  if (const char* home = std::getenv("HOME"); home && *home)
    return std::filesystem::path(home) / ".cache" / "taa-harness" / sub;
  return {};
}

}  // namespace taa
