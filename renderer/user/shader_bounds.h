// What one user shader may cost before it reaches glslang and the driver (docs/trust.md,
// "Limits"). glslang recurses over the syntax tree, so a long expression overflows its stack;
// its preprocessor expands macros and includes without bound; a driver compiles whatever
// private or shared memory the SPIR-V asks for. Each bound below is checked where the cost
// arises, and everything glslang does runs in a child process under compileLimits().
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "user/compile_sandbox.h"

namespace taa::user {

inline constexpr uint64_t kMaxShaderFileBytes = uint64_t(1) << 20;    // the shader, each header
inline constexpr size_t kMaxIncludeDepth = 32;                         // nested #include
inline constexpr size_t kMaxIncludes = 1024;                           // resolved, counting repeats
inline constexpr uint64_t kMaxIncludedBytes = uint64_t(16) << 20;      // all headers read, together
inline constexpr uint64_t kMaxPreprocessedBytes = uint64_t(4) << 20;  // after macros and includes
// CPU for the preprocessor alone: a 4 MiB expansion takes well under a second, a macro bomb
// would take minutes.
inline constexpr std::chrono::milliseconds kPreprocessCpu{3000};
inline constexpr int kMaxExpressionDepth = 16384;  // operators and brackets nested in one statement
// Private (Function and Private storage) bytes per invocation: a per-pixel resolve needs a few
// hundred bytes (a 5x5 neighbourhood of vec4 is 400); lavapipe compiles arrays far beyond this
// into code that takes minutes per dispatch.
inline constexpr uint64_t kMaxPrivateBytes = uint64_t(16) << 10;
// Numbers in constant arrays (lookup tables): Mesa's compiler takes time quadratic in a
// dynamically indexed table's size (on lavapipe 1 s for 256 floats, 17 s for 1,024, minutes
// for 4,096), once per shader and device before its pipeline cache has it.
inline constexpr uint64_t kMaxConstantArrayNumbers = 1024;
// Workgroup (shared) memory: Vulkan's guaranteed minimum of maxComputeSharedMemorySize, so a
// shader that loads runs on every device.
inline constexpr uint64_t kMaxSharedBytes = uint64_t(16) << 10;

inline constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

// A user's shader or header, read whole within kMaxShaderFileBytes, less a leading UTF-8
// byte-order mark; a file missing, unreadable, or over the bound is a ShaderCompileError
// starting with `what`.
std::string readShaderText(const std::filesystem::path& file, const std::string& what);

// The child process glslang runs in: CPU, memory, wall time and its thread's stack.
SandboxLimits compileLimits();

// Empty, or where in `preprocessed` (glslang's preprocessor output, with its #line
// directives; `file` names its first line) a statement nests deeper than
// kMaxExpressionDepth, as "FILE:LINE: ...". The depth counted is an upper bound of the
// syntax tree's: every operator of a chain and every bracket adds one.
std::string expressionDepthProblem(const std::string& preprocessed, const std::string& file);

// Empty, or which of kMaxPrivateBytes, kMaxSharedBytes and kMaxConstantArrayNumbers the
// module's variables and constants exceed,
// with array lengths that specialization constants set taken from `specValues` (SpecId ->
// the 32 bits taa.shader_params gives), else from their defaults.
std::string spirvMemoryProblem(const std::vector<uint32_t>& words,
                               const std::map<uint32_t, uint32_t>& specValues = {});

}  // namespace taa::user
