// How a user's shader finds its #includes: beside the including file, then in the installed
// headers (taa_user.h), never outside those two folders, within the include bounds of
// user/shader_bounds.h. glslang asks it during the compile (user/glsl_compiler.cpp).
#pragma once

#include <glslang/Public/ShaderLang.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace taa::user {

// Resolves #include against the including file's folder, then the installed headers. A file
// found beside the includer but outside the allowed folders is refused, not skipped, so a
// header can never be taken from somewhere the user did not mean.
class UserIncluder : public glslang::TShader::Includer {
 public:
  UserIncluder(std::filesystem::path root, std::filesystem::path headerDir);

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* r) override;

  // The real paths of the headers read, in order (repeats included).
  const std::vector<std::filesystem::path>& files() const { return files_; }
  // Why the last include failed or a bound stopped the includes; "" when none did.
  const std::string& problem() const { return problem_; }

 private:
  IncludeResult* resolve(const char* header, const char* includer, size_t depth, bool local);
  IncludeResult* stop(const std::string& why);
  // Inside the case's folder or the installed headers, by the path's text or its real path.
  bool allowed(const std::filesystem::path& p);
  const std::filesystem::path& rootReal();
  const std::filesystem::path& headerReal();

  std::filesystem::path root_, headerDir_, rootReal_, headerReal_;
  std::vector<std::filesystem::path> files_;
  std::string problem_;
  bool stopped_ = false;
  size_t count_ = 0;
  uint64_t bytes_ = 0;
};

}  // namespace taa::user
