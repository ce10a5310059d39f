// Compiles a user's compute shader, GLSL or HLSL, at run time with glslang (the library,
// not the glslangValidator program; HLSL through its HLSL front end), so a resolve written
// outside the source tree runs without a rebuild. `#include "x"` is looked up beside the including file (which must stay inside
// `root`, as scenes must stay inside their case's folder) and then in the installed header
// folder (taa_user.h, taa_user.hlsli). SPIR-V is cached by the content of the source and of every file it
// includes, so a second run skips glslang and an edited header is never served stale.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "api/loader_errors.h"  // ShaderCompileError
#include "user/declared_constants.h"
#include "user/shader_bounds.h"

namespace taa::user {

enum class ShaderLanguage { Glsl, Hlsl };
const char* languageName(ShaderLanguage l);  // "glsl", "hlsl"

// A file's language by its extension: .hlsl is HLSL, anything else GLSL.
ShaderLanguage languageOf(const std::filesystem::path& file);

struct CompileOptions {
  std::filesystem::path root;       // includes must resolve inside this folder
  std::filesystem::path headerDir;  // the installed taa_user.h folder; empty: userHeaderDir()
  std::filesystem::path cacheDir;   // empty: userShaderCacheDir() (spirv_cache.h)
  ShaderLanguage language = ShaderLanguage::Glsl;
  std::string entry = "main";  // HLSL's entry point, kept as the SPIR-V's (GLSL's is main)
  // taa.shader_defines, valid (api/shader_defines.h): #define lines before the source, part of the
  // cache key.
  std::vector<std::string> defines;
  // The preprocessor's CPU bound; the tests of the bound itself shorten it.
  std::chrono::milliseconds preprocessCpu = kPreprocessCpu;
};

struct CompiledShader {
  std::vector<uint32_t> spirv;
  std::vector<std::filesystem::path> includes;  // real paths of every included file
  bool fromCache = false;
  // What this run did to get the SPIR-V, for the run log: "compiled by glslang: no cache
  // entry", "recompiled by glslang: FILE changed since it was cached", "from the cache".
  // The first lookup of a shader in a process decides it: the case's validation compiles,
  // and the renderer's second lookup must not then claim the cache served it.
  std::string provenance;
  // The capabilities its preprocessed text declares (#pragma taa_supports(NAME), which the
  // headers' TAA_SUPPORTS_* macros write), sorted.
  std::vector<std::string> capabilities;
  // The specialization constants its source declares, read or not (declared_constants.h).
  std::vector<DeclaredConstant> constants;
};

// Throws ShaderCompileError (bad shader or path); a cache that cannot be written is said in
// `provenance` (spirv_cache.h), not thrown.
CompiledShader compileComputeShader(const std::filesystem::path& source,
                                    const CompileOptions& options);

// Where taa_user.h is: beside the SPIR-V the harness loads (vk::shaderDir()/include).
std::filesystem::path userHeaderDir();

}  // namespace taa::user
