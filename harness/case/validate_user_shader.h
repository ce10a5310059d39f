// taa.shader, taa.shader_params and taa.shader_clamps: the path rules scenes follow, the
// built-in settings a user's resolve would ignore, and the shader itself, compiled when the
// case loads so that a compile error or a parameter the shader does not declare is bad
// input (exit 2) naming the file, the key and the fix, before anything renders.
#pragma once

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "spec/checked_case.h"

namespace taa::cases {

// Entries of taa.shader_params a case may give (docs/trust.md): more than any shader declares.
inline constexpr size_t kMaxShaderParams = 256;

// (key, message) pairs; empty when the case has no user shader or it is valid.
std::vector<std::pair<std::string, std::string>> userShaderProblems(
    const spec::CheckedCase& spec, const std::set<std::string>& present);

}  // namespace taa::cases
