// The on-disk cache of users' SPIR-V (compileComputeShader's): an entry per key of the
// compile's inputs, valid while every file the shader included still hashes as it did.
#pragma once

#include <filesystem>
#include <string>

#include "user/glsl_compiler.h"  // CompiledShader

namespace taa::user {

// $TAA_SHADER_CACHE, else $XDG_CACHE_HOME/taa-harness/spirv, else ~/.cache/taa-harness/spirv;
// empty (no cache: every shader compiles) when none of them is set.
std::filesystem::path userShaderCacheDir();

// The cache entry KEY.deps lists the SPIR-V's hash, each include's real path and hash, and the
// capabilities and specialization constants (type, id, name) the shader declares; KEY.spv holds
// the words. A hit needs every include unchanged and the words intact; on a miss `why` says
// what changed ("" when there is no entry at all, or no folder). Anything under an entry's
// name that is not a regular file (a FIFO, a device, a link) is a miss, never waited on.
bool readSpirvCache(const std::filesystem::path& dir, const std::string& key, CompiledShader& out,
                    std::string& why);

// Writes entry KEY (the words first, so a deps file never names SPIR-V that is not there).
// Returns "" when written, else why not (no folder, one that cannot be written, something not a
// file under the entry's name): the cache only saves compile time, so its failure costs the
// next run a compile, never this one its shader.
std::string writeSpirvCache(const std::filesystem::path& dir, const std::string& key,
                            const CompiledShader& c);

}  // namespace taa::user
