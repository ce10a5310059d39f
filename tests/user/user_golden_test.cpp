// A user shader's goldens and its run log, through the harness as a user runs it: editing a
// file the shader #includes makes its goldens stale (the include is part of the case's input
// hash), and the log's SPIR-V line says what happened: compiled on an empty cache, from the
// cache on a warm one, recompiled naming the include after it changed.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/process.h"

namespace {

namespace fs = std::filesystem;

class UserGoldenTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(TAA_TEST_OUT) / "user_golden";
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "cases" / "lib");
    std::ofstream(dir_ / "cases" / "lib" / "gain.glsl") << "const float kGain = 0.5;\n";
    std::ofstream(dir_ / "cases" / "tinted.comp") << R"(#version 450
#include "taa_user.h"
#include "lib/gain.glsl"
void main() {
  ivec2 p;
  if (!taa_pixel(p)) return;
  imageStore(taa_output, p, vec4(taa_color_at(p) * kGain, 1.0));
}
)";
    std::ofstream(dir_ / "cases" / "tinted.json") << R"({"scene": {"builtin": "checkerboard"},
      "render": {"width": 48, "height": 32}, "script": {"frames": 2},
      "taa": {"shader": "tinted.comp"}})";
  }
  // Runs the case and returns its results.json entry; the exit code into `code`.
  nlohmann::json run(int& code) {
    const auto r = taa::test::runHarness("run " + (dir_ / "cases" / "tinted.json").string() +
                                             " --out " + (dir_ / "out").string(),
                                         env());
    code = r.exitCode;
    output_ = r.output;
    std::ifstream in(dir_ / "out" / "results.json");
    return nlohmann::json::parse(in)["cases"][0];
  }
  static std::string spirvLine(const nlohmann::json& c) {
    for (const auto& line : c["log"])
      if (line.get<std::string>().find("pass user_resolve") != std::string::npos) return line;
    return "";
  }
  std::string env() const { return "TAA_SHADER_CACHE=" + (dir_ / "cache").string(); }
  fs::path dir_;
  std::string output_;
};

TEST_F(UserGoldenTest, IncludeEditMakesGoldensStaleAndTheCacheLineTellsTheTruth) {
  int code = -1;
  auto c = run(code);
  EXPECT_NE(spirvLine(c).find("SPIR-V compiled by glslang: no cache entry"), std::string::npos)
      << spirvLine(c);
  const auto bless = taa::test::runHarness(
      "bless " + (dir_ / "cases" / "tinted.json").string() + " --reason 'first version'", env());
  ASSERT_EQ(bless.exitCode, 0) << bless.output;

  c = run(code);
  EXPECT_EQ(code, 0) << output_;
  EXPECT_EQ(c["status"], "pass");
  EXPECT_NE(spirvLine(c).find("SPIR-V from the cache"), std::string::npos) << spirvLine(c);

  // Only the include changes: the shader's own text, and so its cache key, stay the same.
  std::ofstream(dir_ / "cases" / "lib" / "gain.glsl") << "const float kGain = 0.25;\n";
  c = run(code);
  EXPECT_EQ(code, 1) << output_;
  EXPECT_EQ(c["status"], "stale") << output_;
  EXPECT_NE(output_.find("STALE tinted"), std::string::npos) << output_;
  EXPECT_NE(spirvLine(c).find("SPIR-V recompiled by glslang: "), std::string::npos) << spirvLine(c);
  EXPECT_NE(spirvLine(c).find("gain.glsl changed since it was cached"), std::string::npos)
      << spirvLine(c);
}

}  // namespace
