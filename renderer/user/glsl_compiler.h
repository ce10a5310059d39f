// Compiles a user's GLSL compute shader at run time with glslang (the library, not the
// glslangValidator program), so a resolve written outside the source tree runs without a
// rebuild. `#include "x"` is looked up beside the including file (which must stay inside
// `root`, as scenes must stay inside their case's folder) and then in the installed header
// folder (taa_user.h). SPIR-V is cached by the content of the source and of every file it
// includes, so a second run skips glslang and an edited header is never served stale.
#pragma once

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"

namespace taa::user {

// The shader does not compile, names a file it may not read, or breaks taa_user.h's contract
// (user_interface.h): bad input. what() is glslang's message with the user's file and line
// first ("my.comp:12: 'x' : undeclared identifier"), or the file and the reason, and the fix.
class ShaderCompileError : public InputError {
 public:
  using InputError::InputError;
};

struct CompileOptions {
  std::filesystem::path root;       // includes must resolve inside this folder
  std::filesystem::path headerDir;  // the installed taa_user.h folder; empty: userHeaderDir()
  std::filesystem::path cacheDir;   // empty: userShaderCacheDir()
};

struct CompiledShader {
  std::vector<uint32_t> spirv;
  std::vector<std::filesystem::path> includes;  // real paths of every included file
  bool fromCache = false;
};

// Throws ShaderCompileError (bad shader or path) or OutputError (the cache cannot be written).
CompiledShader compileComputeShader(const std::filesystem::path& source,
                                    const CompileOptions& options);

// Where taa_user.h is: beside the SPIR-V the harness loads (vk::shaderDir()/include).
std::filesystem::path userHeaderDir();

// $TAA_SHADER_CACHE, else $XDG_CACHE_HOME/taa-harness/spirv, else ~/.cache/taa-harness/spirv.
std::filesystem::path userShaderCacheDir();

}  // namespace taa::user
