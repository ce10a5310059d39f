// A user-shader test's scratch folder, named after the test: src/ is the shader's root (its
// includes may not leave it), cache/ the SPIR-V cache, and the installed taa_user.h is the
// header folder.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "user/glsl_compiler.h"

namespace taa::test {

class ShaderFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::path(TAA_TEST_OUT) / info->test_suite_name() / info->name();
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_ / "src");
    options_.root = dir_ / "src";
    options_.headerDir = user::userHeaderDir();  // the generated header, as a user has it
    options_.cacheDir = dir_ / "cache";
  }
  // Writes `text` as src/NAME (folders created), byte for byte.
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const std::filesystem::path p = dir_ / "src" / name;
    std::filesystem::create_directories(p.parent_path());
    std::ofstream(p, std::ios::binary) << text;
    return p;
  }
  // The message of compiling `file`, which must be refused.
  std::string compileError(const std::filesystem::path& file) {
    try {
      user::compileComputeShader(file, options_);
    } catch (const user::ShaderCompileError& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " compiled";
    return {};
  }
  std::filesystem::path dir_;
  user::CompileOptions options_;
};

}  // namespace taa::test
