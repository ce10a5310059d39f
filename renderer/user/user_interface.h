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
#include "user/declared_constants.h"

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
  kUserParams = TAA_USER_BINDING_PARAMS,  // loose uniforms ($Global), filled by name
};

// A member of the shader's loose-uniform block (HLSL's $Global, or a GLSL block at
// TAA_USER_BINDING_PARAMS), set by name from taa.shader_params.
struct UserUniform {
  std::string name;
  ParamType type = ParamType::Float;  // its components' (HLSL's bool is a uint in SPIR-V)
  // SPIR-V's shape: `columns` vectors of `rows` components (a scalar 1x1, a vector 1xN). The
  // first index a shader writes picks the column, in GLSL (m[c]) and HLSL (M[r]) alike.
  uint32_t columns = 1, rows = 1;
  uint32_t offset = 0, matrixStride = 0;
  bool rowMajor = false;
  bool supported = true;  // arrays and structs are not: left zero, refused if set
  uint32_t count() const { return columns * rows; }
  std::string typeName() const;  // "float", "float4", "float4x4", "int2"; "array or struct"
};

// The most bytes the loose-uniform block may have (Vulkan's guaranteed maxUniformBufferRange).
inline constexpr uint32_t kMaxUserUniformBytes = 16384;

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
  // Constants its source declares that its SPIR-V no longer has (HLSL's compile removes those
  // its code never reads): a case may set them, to no effect, and is told so.
  std::vector<DeclaredConstant> unread;
  // Its loose-uniform block: the members (by offset) and the block's size; none, 0 bytes.
  std::vector<UserUniform> uniforms;
  uint32_t uniformBytes = 0;
  std::string uniformBlock;  // the block's name ("$Global")

  const UserParam* param(const std::string& name) const;
  const DeclaredConstant* unreadParam(const std::string& name) const;
  const UserUniform* uniform(const std::string& name) const;
};

// The most invocations a user's workgroup may have: what every desktop driver and lavapipe
// offer (Vulkan's minimum is 128; the pipeline's creation checks the device's own limit).
inline constexpr uint32_t kMaxUserWorkgroupInvocations = 1024;

// taa_user.h: a specialization constant's id runs "from 0 to 99".
inline constexpr uint32_t kMaxUserConstantId = 99;

// Throws ShaderCompileError naming `name` when the shader breaks taa_user.h's contract
// (no output image, a history read without its write, an unsupported history format,
// an unnamed specialization constant, a workgroup that is not flat, too large or set by
// specialization constants).
UserInterface reflectUserInterface(const std::vector<uint32_t>& spirv, const std::string& name);

// Fills u.unread: those of `declared` (the source's constants) that u.params lacks.
void noteUnreadConstants(UserInterface& u, const std::vector<DeclaredConstant>& declared);

}  // namespace taa::user
