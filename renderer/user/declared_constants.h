// The specialization constants a shader's source declares, read from its preprocessed text.
// HLSL's compile (glslang with spirv-opt's legalization) removes a constant its code never
// reads, so reflection alone cannot tell such a constant (Playdead's motion_scale with motion
// blur compiled out) from a name the user mistyped: this list can. A case setting a declared
// but removed constant runs with a note; a name the source never declares is refused.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "api/user_shader.h"  // ParamType

namespace taa::user {

struct DeclaredConstant {
  std::string name;
  ParamType type = ParamType::Float;
  int64_t id = -1;  // its constant_id as written (at most kConstantIdCap), -1 if not a number
};

// Ids are read up to this (2^40) and saturate there: far past any valid one (0 to 99), and a
// number of any length neither overflows nor reads as a smaller one.
inline constexpr int64_t kConstantIdCap = int64_t(1) << 40;

// Every `layout(constant_id = N) const T name` (GLSL) and `[[vk::constant_id(N)]] const T name`
// (HLSL) in `preprocessed`, in order, but for the header's own (taa_*) and those whose type
// is not a scalar a constant can have. At most kMaxDeclaredConstants are kept.
std::vector<DeclaredConstant> declaredConstants(const std::string& preprocessed);

// constant_id runs from 0 to 99 (taa_user.h): more declarations than that cannot all be valid.
inline constexpr size_t kMaxDeclaredConstants = 100;

}  // namespace taa::user
