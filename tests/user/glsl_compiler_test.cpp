// The run-time compiler of users' resolves: good shaders compile, errors name the file and
// line, #include is resolved beside the includer and in the installed header folder and never
// outside the shader's folder, and SPIR-V is cached by the content of every file it reads.
#include "user/glsl_compiler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/shader_folder.h"
#include "user/user_interface.h"
#include "user/user_resolve.h"

namespace taa::user {
namespace {

namespace fs = std::filesystem;

class GlslCompilerTest : public test::ShaderFolderTest {
 protected:
  std::string compileError(const fs::path& file) {
    try {
      compileComputeShader(file, options_);
    } catch (const ShaderCompileError& e) {
      return e.what();
    }
    ADD_FAILURE() << file << " compiled";
    return {};
  }
};

const char* kPassThrough = R"(#version 450
#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p), 1.0));
}
)";

TEST_F(GlslCompilerTest, CompilesAShaderAgainstTheInstalledHeader) {
  const auto c = compileComputeShader(write("pass.comp", kPassThrough), options_);
  ASSERT_GT(c.spirv.size(), 5u);
  EXPECT_EQ(c.spirv[0], 0x07230203u);
  EXPECT_FALSE(c.fromCache);
  ASSERT_EQ(c.includes.size(), 1u);
  EXPECT_EQ(c.includes[0].filename(), "taa_user.h");
  const UserInterface u = reflectUserInterface(c.spirv, "pass.comp");
  EXPECT_FALSE(u.depth || u.velocity || u.ids || u.normal || u.prevDepth || u.prevIds ||
               u.prevNormal);
  EXPECT_FALSE(u.history[0] || u.history[1]);
  EXPECT_TRUE(u.params.empty());
}

TEST_F(GlslCompilerTest, SyntaxErrorNamesFileAndLine) {
  const auto file = write(
      "broken.comp",
      "#version 450\n#include \"taa_user.h\"\nvoid main() {\n  float x = undeclared_thing;\n}\n");
  const std::string msg = compileError(file);
  EXPECT_NE(msg.find(file.string() + ":4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("undeclared_thing"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, ErrorInsideAnIncludeNamesTheHeader) {
  write("lib/helpers.glsl", "vec3 helper() {\n  return nope;\n}\n");
  const auto file = write(
      "main.comp",
      "#version 450\n#include \"taa_user.h\"\n#include \"lib/helpers.glsl\"\nvoid main() {}\n");
  const std::string msg = compileError(file);
  EXPECT_NE(msg.find("helpers.glsl:2:"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, IncludeBesideTheShaderIsUsedAndRecorded) {
  write("lib/tint.glsl", "vec3 tint(vec3 c) { return c * 0.5; }\n");
  const auto c = compileComputeShader(write("tinted.comp", R"(#version 450
#include "taa_user.h"
#include "lib/tint.glsl"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(tint(taa_color_at(p)), 1.0));
}
)"),
                                      options_);
  ASSERT_EQ(c.includes.size(), 2u);
  EXPECT_EQ(c.includes[1].filename(), "tint.glsl");
}

TEST_F(GlslCompilerTest, MissingIncludeIsNamed) {
  const auto file =
      write("missing.comp", "#version 450\n#include \"not_there.glsl\"\nvoid main() {}\n");
  const std::string msg = compileError(file);
  EXPECT_NE(msg.find("#include \"not_there.glsl\" not found"), std::string::npos) << msg;
  EXPECT_NE(msg.find("missing.comp"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, IncludeOutsideTheFolderIsRefused) {
  std::ofstream(dir_ / "secret.glsl") << "vec3 secret() { return vec3(1); }\n";
  const auto file =
      write("escape.comp", "#version 450\n#include \"../secret.glsl\"\nvoid main() {}\n");
  const std::string msg = compileError(file);
  EXPECT_NE(msg.find("outside the shader's folder"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, ShaderOutsideTheRootIsRefused) {
  std::ofstream(dir_ / "outside.comp") << kPassThrough;
  const std::string msg = compileError(dir_ / "outside.comp");
  EXPECT_NE(msg.find("outside.comp"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, SecondCompileComesFromTheCacheUntilAnIncludeChanges) {
  write("lib/k.glsl", "const float K = 0.5;\n");
  const auto file = write("cached.comp", R"(#version 450
#include "taa_user.h"
#include "lib/k.glsl"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * K, 1.0));
}
)");
  const auto first = compileComputeShader(file, options_);
  const auto second = compileComputeShader(file, options_);
  EXPECT_FALSE(first.fromCache);
  EXPECT_TRUE(second.fromCache);
  EXPECT_EQ(first.spirv, second.spirv);
  EXPECT_EQ(first.includes, second.includes);
  // Same main file, edited header: a stale cache entry would keep K = 0.5.
  write("lib/k.glsl", "const float K = 0.25;\n");
  const auto third = compileComputeShader(file, options_);
  EXPECT_FALSE(third.fromCache);
  EXPECT_NE(third.spirv, first.spirv);
  // A corrupted entry is recompiled, not used.
  for (const auto& e : fs::directory_iterator(options_.cacheDir))
    if (e.path().extension() == ".spv") std::ofstream(e.path(), std::ios::binary) << "garbage!";
  const auto fourth = compileComputeShader(file, options_);
  EXPECT_FALSE(fourth.fromCache);
  EXPECT_EQ(fourth.spirv, third.spirv);
}

TEST_F(GlslCompilerTest, ReflectionFindsInputsHistoriesAndParameters) {
  const auto c = compileComputeShader(write("decl.comp", R"(#version 450
#define TAA_USE_VELOCITY
#define TAA_USE_PREV_DEPTH
#define TAA_HISTORY0_FORMAT r16f
#include "taa_user.h"
layout(constant_id = 0) const float gamma = 1.25;
layout(constant_id = 1) const bool clip = true;
layout(constant_id = 2) const int taps = 3;
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  vec2 v = texelFetch(taa_velocity, p, 0).xy;
  float d = texelFetch(taa_prev_depth, p, 0).x;
  float h = texture(taa_history0, vec2(p)).x;
  imageStore(taa_history0_out, p, vec4(h));
  imageStore(taa_output, p, vec4(taa_color_at(p) * gamma * float(taps) * (clip ? 1.0 : d), v.x));
}
)"),
                                      options_);
  const UserInterface u = reflectUserInterface(c.spirv, "decl.comp");
  EXPECT_TRUE(u.velocity);
  EXPECT_TRUE(u.prevDepth);
  EXPECT_FALSE(u.depth || u.ids || u.normal || u.prevIds || u.prevNormal);
  ASSERT_TRUE(u.history[0].has_value());
  EXPECT_EQ(*u.history[0], VK_FORMAT_R16_SFLOAT);
  EXPECT_FALSE(u.history[1].has_value());
  ASSERT_EQ(u.params.size(), 3u);
  EXPECT_EQ(u.params[0].name, "gamma");
  EXPECT_EQ(u.params[0].type, ParamType::Float);
  EXPECT_EQ(u.params[1].name, "clip");
  EXPECT_EQ(u.params[1].type, ParamType::Bool);
  EXPECT_EQ(u.params[1].defaultBits, 1u);
  EXPECT_EQ(u.params[2].type, ParamType::Int);
  EXPECT_EQ(u.params[2].defaultBits, 3u);

  const GBufferNeeds needs = userNeeds(u);
  EXPECT_TRUE(needs.velocity && needs.prevDepth);
  EXPECT_FALSE(needs.depth || needs.ids || needs.normal || needs.prevIds || needs.prevNormal ||
               needs.prevVelocity);

  spec::TaaSpec t;
  t.shader = "decl.comp";
  t.shader_params = {{"gamma", 2.0f}, {"clip", 0.0f}, {"taps", 5.0f}};
  EXPECT_TRUE(userParamProblems(t, u).empty());
  EXPECT_EQ(userSpecConstants(t, u).describe(), "0=1073741824 1=0 2=5");
  t.shader_params = {{"gama", 2.0f}, {"clip", 0.5f}, {"taps", 1.5f}};
  const auto problems = userParamProblems(t, u);
  ASSERT_EQ(problems.size(), 3u);
  EXPECT_NE(problems[0].find("taa.shader_params[0].name: 'gama'"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[0].find("gamma (float), clip (bool), taps (int)"), std::string::npos)
      << problems[0];
  EXPECT_NE(problems[1].find("taa.shader_params[1].value: clip is declared bool"),
            std::string::npos);
  EXPECT_NE(problems[2].find("taa.shader_params[2].value: taps is declared int"),
            std::string::npos);
}

TEST_F(GlslCompilerTest, ShaderWithoutOutputBreaksTheContract) {
  const auto c = compileComputeShader(
      write("nothing.comp", "#version 450\nlayout(local_size_x = 8) in;\nvoid main() {}\n"),
      options_);
  EXPECT_THROW(reflectUserInterface(c.spirv, "nothing.comp"), std::runtime_error);
}

}  // namespace
}  // namespace taa::user
