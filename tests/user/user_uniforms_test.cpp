// Loose uniforms (issue 45): an engine's resolve declares material properties as plain
// globals (HLSL's $Global; a GLSL block at TAA_USER_BINDING_PARAMS). They are reflected from
// the SPIR-V and filled by member name from taa.shader_params, so such a shader runs unedited;
// a value of the wrong type or size is refused naming the member and what it takes.
#include "user/user_uniforms.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <nlohmann/json.hpp>

#include "api/user_shader.h"
#include "case/case_loader.h"
#include "support/case_problems.h"
#include "support/gpu.h"
#include "user/glsl_compiler.h"
#include "user/user_interface.h"

namespace {

namespace fs = std::filesystem;
using namespace taa;

// One resolve body, declared two ways: three loose globals, as a Unity TAA declares them (a
// vector, a scalar and a matrix), and its twin with the same values written into the code.
const std::string kBody = R"(TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
  float4 c = mul(_ColorMatrix, float4(taa_color_at(p), 1.0));
  taa_output[p] = c * _Sharpness + _FinalBlendParameters;
}
)";

const std::string kLoose = R"(#include "taa_user.hlsli"
float4 _FinalBlendParameters;
float _Sharpness;
float4x4 _ColorMatrix;
)" + kBody;

const std::string kBaked = R"(#include "taa_user.hlsli"
static const float4 _FinalBlendParameters = float4(0.25, 0.0, 0.5, 1.0);
static const float _Sharpness = 0.75;
static const float4x4 _ColorMatrix = float4x4(0, 1, 0, 0,  1, 0, 0, 0,  0, 0, 0.5, 0,  0, 0, 0, 1);
)" + kBody;

const char* kParams = R"([
  {"name": "_FinalBlendParameters", "value": [0.25, 0.0, 0.5, 1.0]},
  {"name": "_Sharpness", "value": 0.75},
  {"name": "_ColorMatrix", "value": [0, 1, 0, 0,  1, 0, 0, 0,  0, 0, 0.5, 0,  0, 0, 0, 1]}])";

class UserUniformsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(TAA_TEST_OUT) / "user_uniforms" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    setenv("TAA_SHADER_CACHE", (dir_ / "cache").c_str(), 1);
    std::ofstream(dir_ / "loose.hlsl") << kLoose;
    std::ofstream(dir_ / "baked.hlsl") << kBaked;
  }
  cases::LoadedCase load(const std::string& shader, const std::string& params) {
    return cases::parseCase(R"({"render": {"width": 32, "height": 18}, "script": {"frames": 2},
      "scene": {"builtin": "checkerboard"}, "taa": {"shader": ")" +
                                shader + R"(", "shader_params": )" + params + "}}",
                            dir_ / "c.json");
  }
  std::vector<std::string> problems(const std::string& params) {
    return test::caseRefusal([&] { load("loose.hlsl", params); });
  }
  fs::path dir_;
};

TEST_F(UserUniformsTest, GlobalsAreReflectedByNameTypeAndOffset) {
  user::CompileOptions o;
  o.root = dir_;
  o.cacheDir = dir_ / "cache";
  o.language = user::ShaderLanguage::Hlsl;
  const auto c = user::compileComputeShader(dir_ / "loose.hlsl", o);
  const user::UserInterface u = user::reflectUserInterface(c.spirv, "loose.hlsl");
  EXPECT_EQ(u.uniformBlock, "$Global");
  ASSERT_EQ(u.uniforms.size(), 3u);
  EXPECT_EQ(u.uniforms[0].name, "_FinalBlendParameters");
  EXPECT_EQ(u.uniforms[0].typeName(), "float4");
  EXPECT_EQ(u.uniforms[1].typeName(), "float");
  EXPECT_EQ(u.uniforms[1].offset, 16u);
  EXPECT_EQ(u.uniforms[2].typeName(), "float4x4");
  EXPECT_EQ(u.uniforms[2].offset, 32u);
  EXPECT_EQ(u.uniformBytes, 96u);
  // Bytes: the matrix in the order the shader indexes it (M[0][1] is the second number),
  // whatever majorness glslang gave the block; an unset member stays zero.
  spec::TaaSpec taa;
  taa.shader_params = {
      {"_Sharpness", {0.75, false, {}}},
      {"_ColorMatrix", {0.0, false, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16}}}};
  const std::vector<uint8_t> bytes = user::userUniformBytes(taa, u);
  ASSERT_EQ(bytes.size(), 96u);
  auto at = [&](uint32_t offset) {
    float f;
    std::memcpy(&f, bytes.data() + offset, 4);
    return f;
  };
  EXPECT_EQ(at(0), 0.0f);  // _FinalBlendParameters, not set
  EXPECT_EQ(at(16), 0.75f);
  const user::UserUniform& m = u.uniforms[2];
  for (uint32_t i = 0; i < 4; ++i)
    for (uint32_t j = 0; j < 4; ++j) {
      const uint32_t offset = m.rowMajor ? m.offset + j * m.matrixStride + 4 * i
                                         : m.offset + i * m.matrixStride + 4 * j;
      EXPECT_EQ(at(offset), float(1 + 4 * i + j)) << "M[" << i << "][" << j << "]";
    }
  EXPECT_EQ(user::describeUserUniforms(taa, u),
            "loose uniforms $Global (96 bytes): _Sharpness=0.75 (float), _ColorMatrix=[1, 2, 3, "
            "4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16] (float4x4); zero, not set: "
            "_FinalBlendParameters (float4)");
}

// GLSL's counterpart: a uniform block at the binding taa_user.h documents.
TEST_F(UserUniformsTest, AGlslBlockAtTheParamsBindingIsTheSame) {
  std::ofstream(dir_ / "block.comp") << R"(#version 450
#include "taa_user.h"
layout(std140, set = 0, binding = TAA_USER_BINDING_PARAMS) uniform Params {
  vec4 blend;
  int taps;
  mat3x2 warp;
};
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, blend * float(taps) + vec4(warp[1], 0.0, 0.0));
}
)";
  user::CompileOptions o;
  o.root = dir_;
  o.cacheDir = dir_ / "cache";
  const auto c = user::compileComputeShader(dir_ / "block.comp", o);
  const user::UserInterface u = user::reflectUserInterface(c.spirv, "block.comp");
  EXPECT_EQ(u.uniformBlock, "Params");
  ASSERT_EQ(u.uniforms.size(), 3u);
  EXPECT_EQ(u.uniforms[1].typeName(), "int");
  EXPECT_EQ(u.uniforms[2].typeName(), "float3x2");  // three columns of two
  spec::TaaSpec taa;
  taa.shader_params = {{"warp", {0.0, false, {1, 2, 3, 4, 5, 6}}}, {"taps", {2.0, false, {}}}};
  const std::vector<uint8_t> bytes = user::userUniformBytes(taa, u);
  float f;
  std::memcpy(&f, bytes.data() + u.uniforms[2].offset + u.uniforms[2].matrixStride, 4);
  EXPECT_EQ(f, 3.0f);  // warp[1][0]: std140 pads each column to 16 bytes
  int32_t taps;
  std::memcpy(&taps, bytes.data() + u.uniforms[1].offset, 4);
  EXPECT_EQ(taps, 2);
  EXPECT_NE(user::uniformValueProblem(u.uniforms[1], {2.5, false, {}})
                .find("an int takes a whole number"),
            std::string::npos);
}

// The bits a number becomes, for constants and uniforms alike, at each type's edges: every
// value the type holds is taken (0 for a uint, INT_MIN for an int), the next one out refused.
TEST(ScalarBits, EachTypeTakesItsWholeRangeAndNothingPast) {
  auto bits = [](user::ParamType t, double n) -> std::optional<uint32_t> {
    uint32_t b = 0;
    if (!user::scalarBits(t, {n, false, {}}, b).empty()) return std::nullopt;
    return b;
  };
  using T = user::ParamType;
  EXPECT_EQ(bits(T::Uint, 0.0), 0u);
  EXPECT_EQ(bits(T::Uint, 4294967295.0), 0xffffffffu);
  EXPECT_FALSE(bits(T::Uint, -1.0));
  EXPECT_FALSE(bits(T::Uint, 4294967296.0));
  EXPECT_FALSE(bits(T::Uint, 0.5));
  EXPECT_EQ(bits(T::Int, -2147483648.0), 0x80000000u);
  EXPECT_EQ(bits(T::Int, -1.0), 0xffffffffu);
  EXPECT_FALSE(bits(T::Int, 2147483648.0));
  EXPECT_EQ(bits(T::Bool, 0.0), 0u);
  EXPECT_EQ(bits(T::Bool, 1.0), 1u);
  EXPECT_FALSE(bits(T::Bool, 2.0));
  EXPECT_EQ(bits(T::Float, 1.0), 0x3f800000u);
  EXPECT_FALSE(bits(T::Float, 1e39));
}

TEST_F(UserUniformsTest, ATypeOrSizeMismatchIsRefusedNamingTheMember) {
  EXPECT_TRUE(problems(kParams).empty());
  auto p = problems(R"([{"name": "_FinalBlendParameters", "value": [1, 2, 3]}])");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("c.json: taa.shader_params[0].value: _FinalBlendParameters is a float4 "
                      "uniform; give a list of 4 numbers, not 3"),
            std::string::npos)
      << p[0];
  p = problems(R"([{"name": "_Sharpness", "value": [1, 2]}])");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("_Sharpness is a float uniform; give one number, not 2"), std::string::npos)
      << p[0];
  p = problems(R"([{"name": "_Sharpness", "value": true}])");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("give a number, not true or false, for a float"), std::string::npos) << p[0];
  p = problems(R"([{"name": "_Sharpnes", "value": 1}])");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("'_Sharpnes' is not a specialization constant or loose uniform of "),
            std::string::npos)
      << p[0];
  EXPECT_NE(p[0].find("did you mean '_Sharpness'?"), std::string::npos) << p[0];
  EXPECT_NE(p[0].find("_ColorMatrix (float4x4 uniform)"), std::string::npos) << p[0];
  p = problems(R"([{"name": "_Sharpness", "value": [1, "x"]}])");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("a list of 1 to 16 finite numbers"), std::string::npos) << p[0];
}

// The report's case header and the run log's pass line list the uniforms' values: a port whose
// values are all loose uniforms read "params: none" there.
TEST_F(UserUniformsTest, TheReportHeaderNamesTheUniformsValues) {
  const std::string line = describeUserShader(load("loose.hlsl", kParams).spec);
  EXPECT_NE(line.find("params: loose uniforms $Global (96 bytes): _FinalBlendParameters=[0.25, 0, "
                      "0.5, 1] (float4), _Sharpness=0.75 (float)"),
            std::string::npos)
      << line;
  EXPECT_EQ(line.find("none"), std::string::npos) << line;
}

// The port runs unedited and renders what the same values written into the code render.
TEST_F(UserUniformsTest, AShaderWithThreeLooseGlobalsRendersAsItsBakedTwin) {
  const auto loose = load("loose.hlsl", kParams);
  const auto baked = load("baked.hlsl", "[]");
  const auto a = test::renderCase(loose.spec, {0, 1});
  const auto b = test::renderCase(baked.spec, {0, 1});
  ASSERT_EQ(a.size(), 2u);
  ASSERT_EQ(b.size(), 2u);
  for (size_t f = 0; f < 2; ++f) EXPECT_EQ(a[f].colorSha256, b[f].colorSha256) << "frame " << f;
  // Not trivially equal: unset, the globals are zero and the frame is black.
  const auto zero = load("loose.hlsl", "[]");
  EXPECT_NE(test::renderCase(zero.spec, {0})[0].colorSha256, a[0].colorSha256);
}

}  // namespace
