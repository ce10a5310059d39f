// What a user's resolve declares, read from its SPIR-V: which inputs of taa_user.h it reads
// (so the pass plan allocates only those G-buffer targets), the history targets it keeps
// with their formats, and its named specialization constants (set by taa.shader_params).
// The binding numbers are taa_user.h's; the two must change together.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace taa::user {

// taa_user.h's bindings.
enum UserBinding : uint32_t {
  kUserFrame = 0,
  kUserColor = 1,
  kUserDepth = 2,
  kUserVelocity = 3,
  kUserIds = 4,
  kUserNormal = 5,
  kUserPrevDepth = 6,
  kUserPrevIds = 7,
  kUserPrevNormal = 8,
  kUserPrevOutput = 9,
  kUserOutput = 10,
  kUserHistory0 = 11,     // previous frame's history 0 (sampled)
  kUserHistory0Out = 12,  // this frame's history 0 (storage)
  kUserHistory1 = 13,
  kUserHistory1Out = 14,
};

enum class ParamType { Bool, Int, Uint, Float };
const char* paramTypeName(ParamType t);

struct UserParam {
  std::string name;
  uint32_t specId = 0;
  ParamType type = ParamType::Float;
  uint32_t defaultBits = 0;  // the declared default, as the 32 bits SPIR-V stores
};

struct UserInterface {
  bool depth = false, velocity = false, ids = false, normal = false;
  bool prevDepth = false, prevIds = false, prevNormal = false;
  // History targets 0 and 1: the format the shader's output image declares, or none.
  std::optional<VkFormat> history[2];
  std::vector<UserParam> params;  // by constant_id

  const UserParam* param(const std::string& name) const;
  std::vector<std::string> paramNames() const;
};

// Throws std::runtime_error naming `name` when the shader breaks taa_user.h's contract
// (no output image, a history read without its write, an unsupported history format,
// an unnamed specialization constant).
UserInterface reflectUserInterface(const std::vector<uint32_t>& spirv, const std::string& name);

}  // namespace taa::user
