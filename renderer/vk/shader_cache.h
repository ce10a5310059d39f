// Where Mesa's shader cache goes. Not under --out: Mesa maps its cache index into memory,
// and when the disk under a mapped file fills, the process dies with SIGBUS instead of
// reporting an error. The cache only saves compile time (it is keyed by shader and driver),
// so it lives in the user's cache folder and is switched off when that folder cannot be
// written or its disk is nearly full.
#pragma once

#include <cstdint>
#include <filesystem>

namespace taa::vk {

// Free space below which the cache is switched off rather than risk filling the disk.
inline constexpr uint64_t kShaderCacheMinFreeBytes = uint64_t(1) << 30;  // 1 GiB

// $TAA_SHADER_CACHE_DIR ("off" or empty: no cache), else $XDG_CACHE_HOME/taa-harness/mesa,
// else $HOME/.cache/taa-harness/mesa; created. Empty (cache off) when it cannot be created
// or written, or its file system has less than kShaderCacheMinFreeBytes free.
std::filesystem::path shaderCacheDir();

}  // namespace taa::vk
