// taa.shader in a case: the shader is compiled when the case loads, so a compile error, an
// unknown or mistyped parameter, a built-in setting it would ignore or a path leaving the
// case's folder is bad input naming the file, the key and the fix.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "invariants/registry.h"
#include "support/case_problems.h"

namespace {

namespace fs = std::filesystem;

class UserCaseTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(TAA_TEST_OUT) / "user_case" /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    setenv("TAA_SHADER_CACHE", (dir_ / "cache").c_str(), 1);
    std::ofstream(dir_ / "mine.comp") << R"(#version 450
#include "taa_user.h"
layout(constant_id = 0) const float alpha = 0.1;
layout(constant_id = 1) const int taps = 1;
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * alpha * float(taps), 1.0));
}
)";
  }
  std::vector<std::string> problems(const std::string& taa) {
    return taa::test::caseRefusal(
        [&] { taa::cases::parseCase(R"({"taa": )" + taa + "}", dir_ / "c.json"); });
  }
  static std::string joined(const std::vector<std::string>& v) {
    std::string s;
    for (const auto& x : v) s += x + "\n";
    return s;
  }
  fs::path dir_;
};

TEST_F(UserCaseTest, ValidShaderAndParamsLoad) {
  EXPECT_TRUE(problems(R"({"shader": "mine.comp", "shader_params": [{"name": "alpha", "value": 0.5},
                                                                     {"name": "taps", "value": 3}]})")
                  .empty());
}

TEST_F(UserCaseTest, UnknownParameterNamesTheDeclaredOnes) {
  const auto p =
      problems(R"({"shader": "mine.comp", "shader_params": [{"name": "beta", "value": 1}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("c.json: taa.shader_params[0].name: 'beta' is not a specialization constant "
                      "or loose uniform"),
            std::string::npos)
      << p[0];
  EXPECT_NE(p[0].find("alpha (float), taps (int)"), std::string::npos) << p[0];
}

TEST_F(UserCaseTest, WrongTypeIsRefused) {
  const auto p =
      problems(R"({"shader": "mine.comp", "shader_params": [{"name": "taps", "value": 2.5}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_params[0].value: taps is declared int"), std::string::npos)
      << p[0];
}

// A parameter missing its value would silently be 0; one missing its name sets nothing.
TEST_F(UserCaseTest, AParameterWithoutItsValueOrNameIsRefused) {
  auto p = problems(R"({"shader": "mine.comp", "shader_params": [{"name": "alpha"}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_params[0].value: is missing; give the constant's value"),
            std::string::npos)
      << p[0];
  p = problems(R"({"shader": "mine.comp", "shader_params": [{"value": 0.5}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_params[0].name: is missing; give the constant's name"),
            std::string::npos)
      << p[0];
}

TEST_F(UserCaseTest, CompileErrorNamesShaderFileAndLine) {
  std::ofstream(dir_ / "bad.comp")
      << "#version 450\n#include \"taa_user.h\"\nvoid main() {\n  oops();\n}\n";
  const auto p = problems(R"({"shader": "bad.comp"})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader: does not compile"), std::string::npos) << p[0];
  EXPECT_NE(p[0].find("bad.comp:4:"), std::string::npos) << p[0];
}

TEST_F(UserCaseTest, BuiltInSettingsAndPathsOutsideAreRefused) {
  auto p = problems(R"({"shader": "mine.comp", "alpha": 0.2})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.alpha: is a setting of the built-in resolve"), std::string::npos)
      << p[0];
  p = problems(R"({"shader": "../mine.comp"})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader: '../mine.comp' leaves the case's folder"), std::string::npos)
      << p[0];
  p = problems(R"({"shader": "mine.comp", "mode": "basic"})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.mode:"), std::string::npos) << p[0];
  p = problems(R"({"shader_clamps": true})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_clamps: applies only to a user's resolve"), std::string::npos)
      << p[0];
}

TEST_F(UserCaseTest, HistoryBoundedOnlyWhenTheShaderDeclaresItClamps) {
  auto loaded = taa::cases::parseCase(R"({"taa": {"shader": "mine.comp"}})", dir_ / "c.json");
  EXPECT_NE(taa::invariants::inapplicable("history_bounded", loaded.spec)
                .find("does not declare that it clamps"),
            std::string::npos);
  loaded = taa::cases::parseCase(R"({"taa": {"shader": "mine.comp", "shader_clamps": true}})",
                                 dir_ / "c.json");
  EXPECT_EQ(taa::invariants::inapplicable("history_bounded", loaded.spec), "");
}

TEST_F(UserCaseTest, BoolParametersTakeTrueAndFalse) {
  std::ofstream(dir_ / "flag.comp") << R"(#version 450
#include "taa_user.h"
layout(constant_id = 0) const bool dim = false;
layout(constant_id = 1) const float gain = 1.0;
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * (dim ? 0.5 : gain), 1.0));
}
)";
  EXPECT_TRUE(problems(R"({"shader": "flag.comp", "shader_params": [{"name": "dim", "value": true}]})").empty());
  EXPECT_TRUE(problems(R"({"shader": "flag.comp", "shader_params": [{"name": "dim", "value": 1}]})").empty());
  const auto p = problems(R"({"shader": "flag.comp", "shader_params": [{"name": "gain", "value": true}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("gain is declared float; give a number, not true or false"), std::string::npos) << p[0];
  // validate --print: every declared constant, typed, and no built-in resolve setting.
  const auto loaded = taa::cases::parseCase(
      R"({"taa": {"shader": "flag.comp", "shader_params": [{"name": "dim", "value": true}]}})",
      dir_ / "c.json");
  const auto printed = taa::cases::resolvedJson(loaded.spec)["taa"];
  EXPECT_FALSE(printed.contains("alpha")) << printed.dump();
  EXPECT_FALSE(printed.contains("history_filter")) << printed.dump();
  EXPECT_FALSE(printed.contains("shader_entry")) << printed.dump();  // GLSL: always main
  ASSERT_EQ(printed["shader_params"].size(), 2u) << printed.dump();
  EXPECT_EQ(printed["shader_params"][0],
            (nlohmann::json{{"name", "dim"}, {"value", true}, {"type", "bool"}, {"given", true}}));
  EXPECT_EQ(printed["shader_params"][1],
            (nlohmann::json{{"name", "gain"}, {"value", 1.0}, {"type", "float"}, {"given", false}}));
}

// HLSL's compile removes a constant its code never reads (Playdead's motion_scale with motion
// blur compiled out): setting it is a note, not a refusal; a name never declared still is.
TEST_F(UserCaseTest, AConstantTheCompileDroppedIsANoteAndATypoStillRefused) {
  std::ofstream(dir_ / "drop.hlsl") << R"(#include "taa_user.hlsli"
[[vk::constant_id(0)]] const float feedback = 0.9;
[[vk::constant_id(1)]] const float motion_scale = 1.0;  // read only by a compiled-out branch
[[vk::constant_id(2)]] const bool motion_blur = false;
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
#ifdef USE_MOTION_BLUR
  taa_output[p] = float4(taa_color_at(p) * motion_scale, 1.0);
#else
  taa_output[p] = float4(taa_color_at(p) * feedback, 1.0);
#endif
}
)";
  const std::string setting =
      R"({"taa": {"shader": "drop.hlsl", "shader_params": [{"name": "motion_scale", "value": 0.5}]}})";
  const auto loaded = taa::cases::parseCase(setting, dir_ / "c.json");
  const auto printed = taa::cases::resolvedJson(loaded.spec)["taa"]["shader_params"];
  ASSERT_EQ(printed.size(), 2u) << printed.dump();  // feedback and the note; motion_blur unset
  EXPECT_EQ(printed[1]["name"], "motion_scale") << printed.dump();
  EXPECT_EQ(printed[1]["value"], 0.5) << printed.dump();
  EXPECT_EQ(printed[1]["unread"], "not read by the shader's code") << printed.dump();
  EXPECT_FALSE(printed[0].contains("unread")) << printed.dump();
  // Still typed by its declaration.
  auto p = problems(
      R"({"shader": "drop.hlsl", "shader_params": [{"name": "motion_scale", "value": true}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("motion_scale is declared float"), std::string::npos) << p[0];
  p = problems(
      R"({"shader": "drop.hlsl", "shader_params": [{"name": "motion_scal", "value": 1}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("'motion_scal' is not a specialization constant or loose uniform of "
                      "drop.hlsl; did you mean "
                      "'motion_scale'?"),
            std::string::npos)
      << p[0];
  // Each repeat once, however many copies came before it.
  p = problems(R"({"shader": "drop.hlsl", "shader_params": [{"name": "feedback", "value": 1},
      {"name": "feedback", "value": 1}, {"name": "feedback", "value": 1}]})");
  EXPECT_EQ(p.size(), 2u) << joined(p);
}

// Keywords from the case: each variant compiles its own SPIR-V (the defines are part of the
// cache key), and a name no define can have is refused by key.
TEST_F(UserCaseTest, ShaderDefinesPickTheVariantAndBadNamesAreRefused) {
  std::ofstream(dir_ / "kw.hlsl") << "\xEF\xBB\xBF"
                                  << R"(#include "taa_user.hlsli"
#ifdef USE_GAIN
[[vk::constant_id(0)]] const float gain = 0.5;
#endif
TAA_NUMTHREADS
void main(uint3 id : SV_DispatchThreadID) {
  int2 p;
  if (!taa_pixel(id, p)) return;
#ifdef USE_GAIN
  taa_output[p] = float4(taa_color_at(p) * gain * TAPS, 1.0);
#else
  taa_output[p] = float4(taa_color_at(p), 1.0);
#endif
}
)";
  // gain exists only in the USE_GAIN variant; TAPS only there too.
  EXPECT_TRUE(problems(R"({"shader": "kw.hlsl", "shader_defines": ["USE_GAIN", "TAPS=3"],
                           "shader_params": [{"name": "gain", "value": 0.25}]})")
                  .empty());
  auto p = problems(R"({"shader": "kw.hlsl", "shader_params": [{"name": "gain", "value": 0.25}]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("'gain' is not a specialization constant or loose uniform"),
            std::string::npos)
      << p[0];
  // A keyword no file of the compile names selects nothing: a typo is refused, with the name
  // it is nearest to; one only the harness's header reads is a keyword like any other.
  p = problems(R"({"shader": "kw.hlsl", "shader_defines": ["USE_GAIM", "TAPS=3"]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("c.json: taa.shader_defines[0]: USE_GAIM appears in none of kw.hlsl's 2 "
                      "file(s)"),
            std::string::npos)
      << p[0];
  EXPECT_NE(p[0].find("so it selects nothing; did you mean 'USE_GAIN'?"), std::string::npos) << p[0];
  EXPECT_TRUE(problems(R"({"shader": "kw.hlsl", "shader_defines": ["TAA_USE_DEPTH"]})").empty());
  p = problems(R"({"shader": "kw.hlsl", "shader_defines": ["USE_GAIN"]})");  // TAPS undefined
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("TAPS"), std::string::npos) << p[0];
  for (const char* bad : {"2FAST", "USE-GAIN", "GL_OES_x", "__FILE", "", "=1"}) {
    SCOPED_TRACE(bad);
    p = problems(std::string(R"({"shader": "kw.hlsl", "shader_defines": [")") + bad + "\"]}");
    ASSERT_EQ(p.size(), 1u) << joined(p);
    EXPECT_NE(p[0].find("c.json: taa.shader_defines[0]: '"), std::string::npos) << p[0];
    EXPECT_NE(p[0].find("is not a name a define can have"), std::string::npos) << p[0];
  }
  p = problems(R"({"shader": "kw.hlsl", "shader_defines": ["A=1\nB"]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_defines[0]: A's value holds a line break"), std::string::npos)
      << p[0];
  p = problems(R"({"shader": "kw.hlsl", "shader_defines": ["A", "A=2"]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_defines[1]: A is defined twice"), std::string::npos) << p[0];
  p = problems(R"({"shader_defines": ["A"]})");
  ASSERT_EQ(p.size(), 1u) << joined(p);
  EXPECT_NE(p[0].find("taa.shader_defines: applies only to a user's resolve"), std::string::npos)
      << p[0];
  // validate --print and the goldens' input hash: the defines are keys of the case.
  const auto one = taa::cases::parseCase(
      R"({"taa": {"shader": "kw.hlsl", "shader_defines": ["USE_GAIN", "TAPS=3"]}})",
      dir_ / "c.json");
  const auto two = taa::cases::parseCase(
      R"({"taa": {"shader": "kw.hlsl", "shader_defines": ["USE_GAIN", "TAPS=4"]}})",
      dir_ / "c.json");
  EXPECT_EQ(taa::cases::resolvedJson(one.spec)["taa"]["shader_defines"],
            (nlohmann::json{"USE_GAIN", "TAPS=3"}));
  EXPECT_NE(one.sha256, two.sha256);
  // A case saved with a byte-order mark reads as the same case.
  EXPECT_NO_THROW(taa::cases::parseCase(
      "\xEF\xBB\xBF" + std::string(R"({"taa": {"shader": "kw.hlsl"}})"), dir_ / "c.json"));
}

TEST_F(UserCaseTest, ACaseNeedingACapabilityTheShaderLacksIsRefused) {
  const auto load = [&](const std::string& shader, const std::string& render) {
    return joined(taa::test::caseRefusal([&] {
      taa::cases::parseCase(R"({"render": )" + render + R"(, "taa": {"shader": ")" + shader + R"("}})",
                            dir_ / "c.json");
    }));
  };
  const std::string up = load("mine.comp", R"({"width": 64, "height": 36, "upsample": 2})");
  EXPECT_NE(up.find("c.json: taa.shader: the case renders at 32x18 under its 64x36 output "
                    "(render.upsample 2), and mine.comp does not declare upsampling"),
            std::string::npos)
      << up;
  EXPECT_NE(up.find("#define TAA_SUPPORTS_UPSAMPLING"), std::string::npos) << up;
  const std::string dyn = load(
      "mine.comp", R"({"width": 64, "height": 36, "scale_schedule": [{"frame": 2, "scale": 0.5}]})");
  EXPECT_NE(dyn.find("does not declare dynamic_resolution"), std::string::npos) << dyn;
  EXPECT_NE(dyn.find("does not declare upsampling"), std::string::npos) << dyn;
  std::ofstream(dir_ / "able.comp") << "#version 450\n#define TAA_SUPPORTS_UPSAMPLING\n"
                                       "#define TAA_SUPPORTS_DYNAMIC_RESOLUTION\n"
                                    << R"(#include "taa_user.h"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(taa_render_pixel(p)), 1.0));
}
)";
  EXPECT_EQ(load("able.comp", R"({"width": 64, "height": 36, "upsample": 2,
                                  "scale_schedule": [{"frame": 2, "scale": 0.5}]})"),
            "");
}

}  // namespace
