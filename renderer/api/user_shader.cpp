#include "api/user_shader.h"

#include "user/define_use.h"
#include "user/shader_bounds.h"
#include "user/user_capabilities.h"
#include "user/user_resolve.h"
#include "user/user_uniforms.h"

namespace taa {

LoadedUserShader::LoadedUserShader(const spec::CaseSpec& spec)
    : shader_(std::make_unique<const UserShader>(loadUserShader(spec))) {}

LoadedUserShader::~LoadedUserShader() = default;

const std::filesystem::path& LoadedUserShader::file() const { return shader_->file; }

const std::filesystem::path& LoadedUserShader::root() const { return shader_->root; }

const std::vector<std::filesystem::path>& LoadedUserShader::includes() const {
  return shader_->includes;
}

bool LoadedUserShader::hlsl() const { return shader_->language == user::ShaderLanguage::Hlsl; }

std::vector<std::string> LoadedUserShader::missingCapabilities(const spec::CaseSpec& spec) const {
  return user::missingCapabilities(spec, shader_->capabilities, spec.taa.shader);
}

std::vector<std::string> LoadedUserShader::paramProblems(const spec::TaaSpec& taa) const {
  return userParamProblems(taa, shader_->interface);
}

std::vector<std::string> LoadedUserShader::defineProblems(const spec::TaaSpec& taa) const {
  std::vector<std::filesystem::path> files{shader_->file};
  files.insert(files.end(), shader_->includes.begin(), shader_->includes.end());
  return user::unusedDefineProblems(taa.shader_defines, files, taa.shader);
}

std::vector<UserParamValue> LoadedUserShader::paramValues(const spec::TaaSpec& taa) const {
  return userParamValues(taa, shader_->interface);
}

std::string LoadedUserShader::uniformsLine(const spec::TaaSpec& taa) const {
  return user::describeUserUniforms(taa, shader_->interface);
}

std::string LoadedUserShader::memoryProblem(const spec::TaaSpec& taa) const {
  return user::spirvMemoryProblem(shader_->spirv, userSpecValues(taa, shader_->interface));
}

bool userShaderIsHlsl(const spec::TaaSpec& taa) {
  return userShaderLanguage(taa) == user::ShaderLanguage::Hlsl;
}

}  // namespace taa
