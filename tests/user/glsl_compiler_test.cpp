// The run-time compiler of users' resolves: good shaders compile, errors name the file and
// line, #include is resolved beside the includer and in the installed header folder and never
// outside the shader's folder (the SPIR-V cache: spirv_cache_test.cpp).
#include "user/glsl_compiler.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/shader_folder.h"
#include "user/spirv_check.h"
#include "user/user_interface.h"
#include "user/user_resolve.h"
#include "vk/spirv_reflect.h"

namespace taa::user {
namespace {

namespace fs = std::filesystem;

using GlslCompilerTest = test::ShaderFolderTest;

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
  // The header's two always-declared inputs, and nothing the shader did not ask for.
  EXPECT_EQ(u.reads, (ResolveInputSet{ResolveInput::Color, ResolveInput::History}));
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

// A variant a port cannot run says so with #error: that line is the message, without the
// preprocessor's echoes of it (each #if still open as "missing #endif").
TEST_F(GlslCompilerTest, AnErrorDirectiveIsTheWholeMessage) {
  for (const char* name : {"stop.comp", "stop.hlsl"}) {
    SCOPED_TRACE(name);
    const bool hlsl = std::string(name).find(".hlsl") != std::string::npos;
    options_.language = hlsl ? ShaderLanguage::Hlsl : ShaderLanguage::Glsl;
    const auto file = write(name, std::string(hlsl ? "" : "#version 450\n") +
                                      "#if 1\n#ifndef NEVER\n#error needs a tile-max pass\n"
                                      "#endif\n#endif\nvoid main() {}\n");
    const std::string msg = compileError(file);
    EXPECT_NE(msg.find(file.string() + ":" + (hlsl ? "3" : "4") + ": '#error' : needs a tile"),
              std::string::npos)
        << msg;
    EXPECT_EQ(msg.find("missing #endif"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("parsing failed"), std::string::npos) << msg;
  }
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

// taa_user.h is generated from the resolve input table: every row offered to a user's shader
// is declared by its macro, at its binding, and reflects back as exactly that input.
TEST_F(GlslCompilerTest, EveryTableInputIsDeclaredByItsMacroAndReflectsAsItself) {
  int offered = 0;
  for (const ResolveInputInfo& i : kResolveInputs) {
    if (i.userBinding < 0 || std::string(i.userMacro) == "TAA_USER_ALWAYS") continue;
    ++offered;
    const std::string file = std::string(i.userName) + ".comp";
    const std::string texel = i.uintTexels
                                  ? "vec4(texelFetch(" + std::string(i.userName) + ", p, 0))"
                                  : "texelFetch(" + std::string(i.userName) + ", p, 0)";
    const auto c = compileComputeShader(
        write(file, "#version 450\n#define " + std::string(i.userMacro) +
                        "\n#include \"taa_user.h\"\nvoid main() {\n  ivec2 p;\n"
                        "  if (!taa_pixel(p)) return;\n  imageStore(taa_output, p, " +
                        texel + ");\n}\n"),
        options_);
    const UserInterface u = reflectUserInterface(c.spirv, file);
    EXPECT_EQ(u.reads, (ResolveInputSet{ResolveInput::Color, ResolveInput::History, i.input}))
        << i.userMacro;
    const vk::ShaderInterface si = vk::reflectSpirv(c.spirv, file);
    EXPECT_NE(si.find(0, uint32_t(i.userBinding)), nullptr) << i.userName;
    if (i.need) {
      EXPECT_TRUE(userNeeds(u).*i.need) << i.userMacro;
    }
  }
  EXPECT_GE(offered, 7);
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
  EXPECT_EQ(u.reads, (ResolveInputSet{ResolveInput::Color, ResolveInput::History,
                                      ResolveInput::Velocity, ResolveInput::PrevDepth}));
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
  t.shader_params = {{"gamma", {2.0}}, {"clip", {0.0, true}}, {"taps", {5.0}}};
  EXPECT_TRUE(userParamProblems(t, u).empty());
  EXPECT_EQ(userSpecConstants(t, u).describe(), "0=1073741824 1=0 2=5");
  EXPECT_EQ(describeUserParams(userParamValues(t, u)),
            "gamma=2 (float), clip=false (bool), taps=5 (int)");
  t.shader_params = {{"taps", {7.0}}};
  EXPECT_EQ(describeUserParams(userParamValues(t, u)),
            "gamma=1.25 (float, default), clip=true (bool, default), taps=7 (int)");
  // true/false is for bools only; a bool also takes 1 or 0.
  t.shader_params = {{"gamma", {1.0, true}}, {"clip", {1.0}}};
  const auto typed = userParamProblems(t, u);
  ASSERT_EQ(typed.size(), 1u);
  EXPECT_NE(typed[0].find("give a number, not true or false, for a float"), std::string::npos)
      << typed[0];
  t.shader_params = {{"gama", {2.0}}, {"clip", {0.5}}, {"taps", {1.5}}};
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

namespace taa::user {
namespace {

const char* kHlslPassThrough = R"(#include "taa_user.hlsli"
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  taa_output[p] = float4(taa_color_at(p), 1.0);
}
)";

TEST_F(GlslCompilerTest, HlslCompilesThroughItsFrontEndWithTheSameInterface) {
  options_.language = ShaderLanguage::Hlsl;
  EXPECT_EQ(languageOf("a/b.HLSL"), ShaderLanguage::Hlsl);
  EXPECT_EQ(languageOf("a/b.comp"), ShaderLanguage::Glsl);
  const auto c = compileComputeShader(write("pass.hlsl", kHlslPassThrough), options_);
  ASSERT_EQ(c.includes.size(), 1u);
  EXPECT_EQ(c.includes[0].filename(), "taa_user.hlsli");
  const UserInterface u = reflectUserInterface(c.spirv, "pass.hlsl");
  // HLSL drops what the shader never reads: even the history it does not sample.
  EXPECT_EQ(u.reads, (ResolveInputSet{ResolveInput::Color}));
  // Textures and samplers apart, HLSL's way: the colour is a sampled image at its binding.
  const vk::ShaderInterface si = vk::reflectSpirv(c.spirv, "pass.hlsl");
  ASSERT_NE(si.find(0, 1), nullptr);
  EXPECT_EQ(si.find(0, 1)->type, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
}

TEST_F(GlslCompilerTest, HlslEntryPointParametersHistoriesAndErrors) {
  options_.language = ShaderLanguage::Hlsl;
  options_.entry = "resolve";
  const auto c = compileComputeShader(write("entry.hlsl", R"(#define TAA_USE_PREV_VELOCITY
#define TAA_HISTORY0_FORMAT rg16f
#include "taa_user.hlsli"
[[vk::constant_id(0)]] const float gain = 0.5;
[[vk::constant_id(3)]] const bool flip = false;
[numthreads(16, 4, 1)]
void resolve(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  float2 v = taa_prev_velocity_uv(p, TAA_PREVIOUS_MINUS_CURRENT);
  taa_history0_out[p] = taa_history0.SampleLevel(taa_linear_clamp, v, 0);
  taa_output[p] = float4(taa_color_at(p) * (flip ? -gain : gain), 1.0);
}
)"),
                                      options_);
  const UserInterface u = reflectUserInterface(c.spirv, "entry.hlsl");
  EXPECT_EQ(u.reads, (ResolveInputSet{ResolveInput::Color, ResolveInput::PrevVelocity}));
  EXPECT_EQ(vk::reflectSpirv(c.spirv, "entry.hlsl").entryPoint, "resolve");
  ASSERT_TRUE(u.history[0].has_value());
  EXPECT_EQ(*u.history[0], VK_FORMAT_R16G16_SFLOAT);
  EXPECT_EQ(u.workgroup[0], 16u);
  EXPECT_EQ(u.workgroup[1], 4u);
  ASSERT_EQ(u.params.size(), 2u);
  EXPECT_EQ(u.params[0].name, "gain");
  EXPECT_EQ(u.params[1].name, "flip");
  EXPECT_EQ(u.params[1].type, ParamType::Bool);

  const auto broken = write("broken.hlsl", "#include \"taa_user.hlsli\"\nTAA_NUMTHREADS\n"
                                           "void resolve(uint3 id : SV_DispatchThreadID) {\n"
                                           "  float x = undeclared_thing;\n}\n");
  const std::string msg = compileError(broken);
  EXPECT_NE(msg.find(broken.string() + ":4:"), std::string::npos) << msg;
  // glslang would quietly run a function called main instead: the harness refuses.
  options_.entry = "nowhere";
  const std::string none = compileError(write("noentry.hlsl", kHlslPassThrough));
  EXPECT_NE(none.find("has no function nowhere to run"), std::string::npos) << none;
}

TEST_F(GlslCompilerTest, ByteOrderMarkAtTheStartOfAShaderOrIncludeIsAccepted) {
  // Unity's files start with one; glslang alone takes it for a token before the first `#`.
  const std::string bom = "\xEF\xBB\xBF";
  write("lib/k.glsl", bom + "#define K 0.5\n");
  const auto file = write("bom.comp", bom + R"(#version 450
#include "taa_user.h"
#include "lib/k.glsl"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * K, 1.0));
}
)");
  const auto c = compileComputeShader(file, options_);
  EXPECT_EQ(c.includes.size(), 2u);
  // The mark holds no line: an error after it keeps its line number.
  const auto broken = write("bom_broken.comp", bom + "#version 450\nvoid main() {\n  x = 1;\n}\n");
  const std::string msg = compileError(broken);
  EXPECT_NE(msg.find(broken.string() + ":3:"), std::string::npos) << msg;
  options_.language = ShaderLanguage::Hlsl;
  compileComputeShader(write("bom.hlsl", bom + kHlslPassThrough), options_);
  // Only at the start: a mark inside the text is still the user's error.
  const std::string inner = compileError(write("mid.hlsl", std::string(kHlslPassThrough) + bom));
  EXPECT_FALSE(inner.empty());
}

// Issue 43: each of these compiled, passed `validate`, and crashed the render (SIGFPE in the
// dispatch's size, SIGSEGV in lavapipe); each is refused with the file and line.
TEST_F(GlslCompilerTest, HlslEntryPointsACorruptDriverWouldRunAreRefusedByRule) {
  options_.language = ShaderLanguage::Hlsl;
  const std::string head = "#include \"taa_user.hlsli\"\n";
  const std::string body =
      "  int2 p;\n  if (!taa_pixel(id, p)) return;\n"
      "  taa_output[p] = float4(taa_color_at(p), 1.0);\n";
  struct Bad {
    const char* file;
    std::string text, says;
  };
  const Bad bad[] = {
      {"zero.hlsl",
       head + "[numthreads(0, 8, 1)]\nvoid main(uint3 id : SV_DispatchThreadID) {\n" + body + "}\n",
       ":3: the entry point main declares a workgroup of (0, 8, 1), with a zero"},
      {"pos.hlsl",
       head +
           "TAA_NUMTHREADS\nvoid main(uint3 id : SV_DispatchThreadID,\n"
           "          float4 pos : SV_Position) {\n" +
           body + "}\n",
       ":4: the entry point main's parameter 'pos' has no compute semantic"},
      {"target.hlsl",
       head + "TAA_NUMTHREADS\nfloat4 main(uint3 id : SV_DispatchThreadID) : SV_Target {\n" + body +
           "  return 1;\n}\n",
       ":3: the entry point main returns a value"},
      {"bogus.hlsl",
       head + "TAA_NUMTHREADS\nvoid main(uint3 id : SV_DispatchThreadID, float4 q : SV_Bogus) {\n" +
           body + "}\n",
       ":3: the entry point main's parameter 'q' has no compute semantic"},
      {"plain.hlsl",
       head + "TAA_NUMTHREADS\nvoid main(uint3 id : SV_DispatchThreadID, uint n) {\n" + body +
           "}\n",
       ":3: the entry point main's parameter 'n' has no compute semantic"},
      {"discard.hlsl",
       head +
           "TAA_NUMTHREADS\nvoid main(uint3 id : SV_DispatchThreadID) {\n  if (id.x == 3) "
           "discard;\n" +
           body + "}\n",
       "discard.hlsl: its SPIR-V is not valid for Vulkan 1.2 (spirv-val: "},
      {"id100.hlsl",
       head +
           "[[vk::constant_id(100)]] const float k = 1.0;\nTAA_NUMTHREADS\n"
           "void main(uint3 id : SV_DispatchThreadID) {\n" +
           body + "}\n",
       "id100.hlsl: specialization constant k has constant_id 100; taa_user.h allows 0 to 99"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.file);
    const auto file = write(b.file, b.text);
    const std::string msg = compileError(file);
    EXPECT_NE(msg.find(b.says), std::string::npos) << msg;
    EXPECT_NE(msg.find(b.file), std::string::npos) << msg;
  }
}

// The interface check behind the validator: an input that is no thread id (here the id's
// BuiltIn decoration turned into a Location, which spirv-val accepts) is refused.
TEST_F(GlslCompilerTest, SpirvWhoseInputIsNoThreadIdIsRefused) {
  options_.language = ShaderLanguage::Hlsl;
  auto words = compileComputeShader(write("ok.hlsl", kHlslPassThrough), options_).spirv;
  EXPECT_EQ(userSpirvProblem(words, "ok.hlsl"), "");
  bool changed = false;
  for (size_t i = 5; i + 3 < words.size(); i += words[i] >> 16)
    if (words[i] == ((4u << 16) | 71u) && words[i + 2] == 11u && words[i + 3] == 28u) {
      words[i + 2] = 30u;  // Location
      words[i + 3] = 0u;
      changed = true;
    }
  ASSERT_TRUE(changed);
  const std::string why = userSpirvProblem(words, "ok.hlsl");
  EXPECT_NE(why.find("ok.hlsl: its entry point takes an input that is not a compute thread id"),
            std::string::npos)
      << why;
  words.resize(3);
  EXPECT_NE(userSpirvProblem(words, "short").find("short: "), std::string::npos);
}

// kPassThrough with `lines` between its #version and its #include.
std::string passThroughWith(const std::string& lines) {
  const std::string text = kPassThrough;
  const size_t afterVersion = text.find('\n') + 1;
  return text.substr(0, afterVersion) + lines + text.substr(afterVersion);
}

TEST_F(GlslCompilerTest, CapabilitiesComeFromTheHeadersMacros) {
  const auto none = compileComputeShader(write("none.comp", kPassThrough), options_);
  EXPECT_TRUE(none.capabilities.empty());
  const std::string both =
      passThroughWith("#define TAA_SUPPORTS_DYNAMIC_RESOLUTION\n#define TAA_SUPPORTS_UPSAMPLING\n");
  const auto compiled = compileComputeShader(write("both.comp", both), options_);
  EXPECT_FALSE(compiled.fromCache);
  EXPECT_EQ(compiled.capabilities, (std::vector<std::string>{"dynamic_resolution", "upsampling"}));
  // Kept with the cache entry: the cached lookup declares the same.
  const auto cached = compileComputeShader(write("both.comp", both), options_);
  EXPECT_TRUE(cached.fromCache);
  EXPECT_EQ(cached.capabilities, compiled.capabilities);
  options_.language = ShaderLanguage::Hlsl;
  const auto hlsl = compileComputeShader(
      write("up.hlsl", std::string("#define TAA_SUPPORTS_UPSAMPLING\n") + kHlslPassThrough), options_);
  EXPECT_EQ(hlsl.capabilities, (std::vector<std::string>{"upsampling"}));
  options_.language = ShaderLanguage::Glsl;
  const std::string msg =
      compileError(write("typo.comp", passThroughWith("#pragma taa_supports(upsamplin)\n")));
  EXPECT_NE(msg.find("taa_supports(upsamplin) names no capability"), std::string::npos) << msg;
}

TEST_F(GlslCompilerTest, OwnWorkgroupIsReadFromSpirvAndBounded) {
  const std::string body = R"(#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p), 1.0));
}
)";
  const auto wide = compileComputeShader(
      write("wide.comp", "#version 450\n#define TAA_OWN_WORKGROUP\nlayout(local_size_x = 32, "
                         "local_size_y = 2) in;\n" + body),
      options_);
  const UserInterface u = reflectUserInterface(wide.spirv, "wide.comp");
  EXPECT_EQ(u.workgroup[0], 32u);
  EXPECT_EQ(u.workgroup[1], 2u);
  const auto deep = compileComputeShader(
      write("deep.comp", "#version 450\n#define TAA_OWN_WORKGROUP\nlayout(local_size_x = 8, "
                         "local_size_y = 8, local_size_z = 2) in;\n" + body),
      options_);
  EXPECT_THROW(reflectUserInterface(deep.spirv, "deep.comp"), std::runtime_error);
  const auto huge = compileComputeShader(
      write("huge.comp", "#version 450\n#define TAA_OWN_WORKGROUP\nlayout(local_size_x = 64, "
                         "local_size_y = 32) in;\n" + body),
      options_);
  EXPECT_THROW(reflectUserInterface(huge.spirv, "huge.comp"), std::runtime_error);
  // A size a specialization constant sets is refused on any axis, constant id 0 included.
  for (const std::string axis : {"x", "y"}) {
    const auto spec = compileComputeShader(
        write("spec_" + axis + ".comp", "#version 450\n#define TAA_OWN_WORKGROUP\nlayout(local_size_" +
                                            axis + "_id = 0) in;\n" + body),
        options_);
    try {
      reflectUserInterface(spec.spirv, "spec.comp");
      ADD_FAILURE() << axis << ": a specialized workgroup size was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("set by specialization constants"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace taa::user
