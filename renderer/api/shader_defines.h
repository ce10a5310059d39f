// taa.shader_defines: preprocessor defines a case, a score lane or a sweep preset gives a
// user's shader, "NAME" (defined as 1, as Unity's keywords are) or "NAME=VALUE", as a
// compiler's -D. They reach glslang as a preamble of #define lines, so they are part of the
// SPIR-V cache key; being keys of the case, they are part of its input hash too.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace taa::user {

inline constexpr size_t kMaxShaderDefines = 64;
inline constexpr size_t kMaxShaderDefineBytes = 256;  // one entry, name and value

// One sentence per entry that is not a define: a NAME that is not an identifier
// ([A-Za-z_][A-Za-z0-9_]*, not starting with GL_ or __, which the preprocessor reserves), a
// VALUE holding a line break or control character, an entry past the bounds, a name given
// twice. Each starts with "taa.shader_defines[i]: ".
std::vector<std::string> shaderDefineProblems(const std::vector<std::string>& defines);

// The #define lines for valid `defines`, in order.
std::string shaderDefinePreamble(const std::vector<std::string>& defines);

}  // namespace taa::user
