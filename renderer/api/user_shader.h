// A user's own resolve (taa.shader) as the harness sees it: loaded, then asked what it read,
// what it declares and what its parameters are. Its SPIR-V and reflected interface stay behind
// the handle (user/user_resolve.h's UserShader), with the Vulkan types they carry.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "api/loader_errors.h"
#include "spec/case_spec.h"

namespace taa {

namespace user {
enum class ParamType { Bool, Int, Uint, Float };
const char* paramTypeName(ParamType t);  // "bool", "int", "uint", "float"
std::optional<ParamType> paramTypeNamed(const std::string& name);  // paramTypeName's inverse
}  // namespace user

struct UserShader;

// Every constant the shader declares with the value it runs with, typed: "alpha=0.1 (float)",
// "clip=true (bool, default)", for the run log, validate --print and the report.
struct UserParamValue {
  std::string name;
  user::ParamType type;
  uint32_t bits;             // as the specialization constant takes it
  bool given;                // by taa.shader_params, else the shader's default
  spec::NumberOrBool value;  // as JSON writes it: a bool as true/false
  // Declared by the source but removed by the compile (its code never reads it): the value
  // the case gives has no effect. Listed only when the case gives one.
  bool unread = false;
};

class LoadedUserShader {
 public:
  // taa.shader compiled (or taken from the cache) and reflected, its includes confined to the
  // case's folder or taa.shader_root (loadUserShader). Throws user::ShaderCompileError on a
  // shader that does not compile or breaks taa_user.h's contract.
  explicit LoadedUserShader(const spec::CaseSpec& spec);
  ~LoadedUserShader();
  LoadedUserShader(const LoadedUserShader&) = delete;
  LoadedUserShader& operator=(const LoadedUserShader&) = delete;

  const std::filesystem::path& file() const;
  const std::filesystem::path& root() const;  // the folder it and its includes stay inside
  const std::vector<std::filesystem::path>& includes() const;  // real paths of every include
  bool hlsl() const;

  // Why `spec` cannot run on it: one sentence per capability the case needs and the shader does
  // not declare (user::missingCapabilities), empty if none.
  std::vector<std::string> missingCapabilities(const spec::CaseSpec& spec) const;
  // taa.shader_params checked against its constants: one "KEY: problem" each (userParamProblems).
  std::vector<std::string> paramProblems(const spec::TaaSpec& taa) const;
  // taa.shader_defines that no file of the compile names (user/define_use.h).
  std::vector<std::string> defineProblems(const spec::TaaSpec& taa) const;
  std::vector<UserParamValue> paramValues(const spec::TaaSpec& taa) const;
  // Its loose uniforms with the values taa.shader_params gives, and those left zero
  // (user::describeUserUniforms); "" when it has none.
  std::string uniformsLine(const spec::TaaSpec& taa) const;
  // Empty, or which memory bound its variables exceed with the constants taa.shader_params
  // gives (user::spirvMemoryProblem).
  std::string memoryProblem(const spec::TaaSpec& taa) const;

 private:
  std::unique_ptr<const UserShader> shader_;
};

// Whether taa.shader is compiled as HLSL: taa.shader_language, else the file's extension.
bool userShaderIsHlsl(const spec::TaaSpec& taa);

// "user shader my.hlsl (hlsl, entry main), params: alpha=0.1 (float)", for a report's case
// header; "" when the case runs the built-in resolve.
std::string describeUserShader(const spec::CaseSpec& spec);

}  // namespace taa
