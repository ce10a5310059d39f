// A user's own temporal resolve (taa.shader): their compute shader, compiled at run time,
// run through the same ResolveStage interface as the built-in resolve. It owns the output
// (ping-pong, so the shader reads its previous output) and the one or two history targets
// the shader declares; it binds only the inputs the shader declares.
#pragma once

#include <filesystem>
#include <map>
#include <memory>

#include "api/user_shader.h"
#include "passes/resolve_stage.h"
#include "spec/case_spec.h"
#include "user/glsl_compiler.h"
#include "user/user_interface.h"
#include "vk/pipeline.h"

namespace taa {

// The shader of a case (taa.shader), compiled (or taken from the cache) and reflected; the
// harness holds it behind api/user_shader.h's LoadedUserShader.
struct UserShader {
  std::filesystem::path file;
  std::filesystem::path root;  // the folder it and its includes stay inside
  std::vector<uint32_t> spirv;
  user::UserInterface interface;
  user::ShaderLanguage language = user::ShaderLanguage::Glsl;
  std::vector<std::filesystem::path> includes;  // real paths of every file it included
  std::vector<std::string> capabilities;        // what it declares it can run
  std::string provenance;                       // user::CompiledShader::provenance
};

// The include root is the case's folder (or taa.shader_root). Throws
// user::ShaderCompileError on a shader that does not compile or breaks taa_user.h's contract.
UserShader loadUserShader(const spec::CaseSpec& spec);

// The language taa.shader is compiled as: taa.shader_language, or by the file's extension.
user::ShaderLanguage userShaderLanguage(const spec::TaaSpec& taa);

// taa.shader_params checked against the declaration: one message per problem (unknown name,
// wrong type, set twice), each naming the key, empty when all are valid.
std::vector<std::string> userParamProblems(const spec::TaaSpec& taa, const user::UserInterface& u);

// taa.shader_params as SpecId -> the constant's 32 bits (valid entries only).
std::map<uint32_t, uint32_t> userSpecValues(const spec::TaaSpec& taa, const user::UserInterface& u);

// The specialization constants taa.shader_params gives (validated beforehand).
vk::SpecConstants userSpecConstants(const spec::TaaSpec& taa, const user::UserInterface& u);

// Every constant the shader declares with the value it runs with (api/user_shader.h).
std::vector<UserParamValue> userParamValues(const spec::TaaSpec& taa, const user::UserInterface& u);
std::string describeUserParams(const std::vector<UserParamValue>& values);  // "none" if empty
// ", defines -DA -DB=2" for taa.shader_defines, "" when there are none.
std::string describeUserDefines(const spec::TaaSpec& taa);
// One sentence per value the shader's code does not read (UserParamValue::unread).
std::vector<std::string> userParamNotes(const std::vector<UserParamValue>& values);

// The G-buffer inputs the shader declares: the plan allocates exactly these.
GBufferNeeds userNeeds(const user::UserInterface& u);

class UserResolvePass : public ResolveStage {
 public:
  UserResolvePass(vk::Context& ctx, const spec::CaseSpec& spec, UserShader shader);
  ~UserResolvePass() override;

  void record(VkCommandBuffer cmd, vk::GpuTimer& timer, const script::FrameState& eyeState, int eye,
              const ResolveInputs& in) override;
  vk::Image& output() override;
  glm::ivec2 outputSize() const override;
  GBufferNeeds needs() const override;
  std::vector<std::string> describe() const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace taa
