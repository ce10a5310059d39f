// What a user's resolve declares, read from its SPIR-V: which inputs of taa_user.h it reads
// (so the pass plan allocates only those G-buffer targets), the history targets it keeps
// with their formats, and its named specialization constants (set by taa.shader_params).
// taa_user.h is generated from the same table (common/resolve_inputs.h), so its bindings
// and these cannot drift apart.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "api/user_shader.h"  // ParamType
#include "common/user_frame.h"
#include "passes/resolve_inputs.h"

namespace taa::user {

// taa_user.h's bindings that are not inputs (the inputs' are their table rows').
enum UserBinding : uint32_t {
  kUserFrame = TAA_USER_BINDING_FRAME,
  kUserOutput = TAA_USER_BINDING_OUTPUT,
  kUserHistory0 = TAA_USER_BINDING_HISTORY0,         // previous frame's history 0 (sampled)
  kUserHistory0Out = TAA_USER_BINDING_HISTORY0_OUT,  // this frame's history 0 (storage)
  kUserHistory1 = TAA_USER_BINDING_HISTORY1,
  kUserHistory1Out = TAA_USER_BINDING_HISTORY1_OUT,
  kUserPointSampler = TAA_USER_BINDING_POINT_SAMPLER,  // HLSL's taa_point_clamp
  kUserLinearSampler = TAA_USER_BINDING_LINEAR_SAMPLER,
};

struct UserParam {
  std::string name;
  uint32_t specId = 0;
  ParamType type = ParamType::Float;
  uint32_t defaultBits = 0;  // the declared default, as the 32 bits SPIR-V stores
};

struct UserInterface {
  ResolveInputSet reads;  // the inputs it declares (taa_color and taa_prev_output always)
  // The workgroup its SPIR-V declares (z is 1): the dispatch covers the output with it.
  uint32_t workgroup[2] = {8, 8};
  // History targets 0 and 1: the format the shader's output image declares, or none.
  std::optional<VkFormat> history[2];
  std::vector<UserParam> params;  // by constant_id

  const UserParam* param(const std::string& name) const;
};

// The most invocations a user's workgroup may have: what every desktop driver and lavapipe
// offer (Vulkan's minimum is 128; the pipeline's creation checks the device's own limit).
inline constexpr uint32_t kMaxUserWorkgroupInvocations = 1024;

// Throws ShaderCompileError naming `name` when the shader breaks taa_user.h's contract
// (no output image, a history read without its write, an unsupported history format,
// an unnamed specialization constant, a workgroup that is not flat, too large or set by
// specialization constants).
UserInterface reflectUserInterface(const std::vector<uint32_t>& spirv, const std::string& name);

}  // namespace taa::user
