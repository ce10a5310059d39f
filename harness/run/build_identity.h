// What produced a run's results besides the cases' own inputs and goldens: this executable, the
// SPIR-V it loads, the CPU feature level lavapipe generates code for, the device asked for and
// whether a missing golden fails (CI). Results are a function of those (the product's
// determinism), so a run may take a case's verdict from an earlier run with the same identity
// and the same inputs and goldens instead of rendering it again (`run --verdict-from`: ctest's
// case tests after their shard, its shards after the main job).
#pragma once

#include <filesystem>
#include <string>

namespace taa::run {

// One line: the executable's GNU build ID (the linker's digest of its code and data; the
// file's own SHA-256 where it has none), a SHA-256 over every .spv file of shaderFolder()
// (names and bytes: an edited shader or another TAA_SHADER_DIR is another identity), the CPU
// feature level (golden/environment.h), the device asked for (--device, else $TAA_DEVICE) and
// whether a case without goldens fails, and whether one without a positive for this environment
// does (--require-exact).
std::string buildIdentity(const std::string& deviceRequest, bool missingGoldenFails,
                          bool requireExact);

// The executable's GNU build ID, else the SHA-256 of its file (computed once).
std::string executableIdentity();

// The SHA-256 over every .spv file of shaderFolder(), as buildIdentity has it: the built-in
// shaders' bytes (`bless --from` refuses a run made from other ones).
std::string spirvIdentity();

// SHA-256 over a folder's regular files (names and bytes, sorted by name); "none" when it
// does not exist: a case's goldens as a run read them.
std::string folderDigest(const std::filesystem::path& dir);

}  // namespace taa::run
