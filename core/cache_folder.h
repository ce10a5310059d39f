// The harness's folder in the user's cache: where the compile caches live (Mesa's, users'
// SPIR-V), outside any --out folder, so runs in any folder share them.
#pragma once

#include <filesystem>
#include <string>

namespace taa {

// $XDG_CACHE_HOME/taa-harness/SUB, else $HOME/.cache/taa-harness/SUB; empty when neither is set.
std::filesystem::path userCacheFolder(const std::string& sub);

}  // namespace taa
