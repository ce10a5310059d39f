// Which installed Vulkan drivers a process rendering on lavapipe loads. To enumerate devices the
// loader loads every driver whose manifest it finds, and the harness then keeps the CPU one: each
// process paid for loading (on a GPU runner, for starting) every other driver, and ctest starts
// hundreds of harness processes (with radeon, intel and intel_hasvk installed beside lavapipe,
// about 25 ms of a 90 ms verdict-only run). A process that wants lavapipe names its manifests
// alone in VK_DRIVER_FILES (vk/context.cpp); any other device, or drivers the user chose, and
// the loader finds them as it always does.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace taa::vk {

// getenv's shape, so tests can give another environment.
using EnvLookup = std::function<const char*(const char*)>;

// The folders the Linux loader reads driver manifests from, in its order: $XDG_CONFIG_HOME
// (~/.config), each of $XDG_CONFIG_DIRS (/etc/xdg), /etc, $XDG_DATA_HOME (~/.local/share) and
// each of $XDG_DATA_DIRS (/usr/local/share:/usr/share), each followed by vulkan/icd.d.
std::vector<std::filesystem::path> driverManifestFolders(const EnvLookup& env);

// Whether a manifest's text is a driver manifest whose library is lavapipe's (a file name
// starting libvulkan_lvp, with or without a folder). Anything else, malformed JSON included, is
// not: the loader alone judges other drivers' manifests.
bool isLavapipeManifest(std::string_view text);

// VK_DRIVER_FILES naming lavapipe's manifests alone, colon-separated in the loader's order
// (a 32-bit manifest beside the 64-bit one is skipped by the loader itself). Empty when none is
// found, and when the user chose drivers: VK_DRIVER_FILES, VK_ICD_FILENAMES or
// VK_ADD_DRIVER_FILES set. Reads at most kMaxManifestsPerFolder entries of each folder and
// kMaxManifestBytes of each, regular files only (a FIFO there cannot hang a run).
inline constexpr int kMaxManifestsPerFolder = 256;
inline constexpr size_t kMaxManifestBytes = 64 * 1024;
std::string lavapipeOnlyDriverFiles(const EnvLookup& env);

}  // namespace taa::vk
