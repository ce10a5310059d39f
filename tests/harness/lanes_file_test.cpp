// A lanes file (score --lanes) as a hostile user writes it: a key of the wrong type, a name
// that is empty or holds a NUL, and 10,000 lanes are refused naming the file and the key, as
// bad input (cases::CaseError, exit 2), before anything renders (issue 43).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "score/score.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

std::string lanesRefusal(const std::string& json) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "lanes_file" / info->name();
  fs::create_directories(dir);
  const fs::path file = dir / "lanes.json";
  std::ofstream(file) << json;
  try {
    score::loadLanes(file);
  } catch (const cases::CaseError& e) {
    std::string all;
    for (const auto& p : e.problems()) all += p + "\n";
    EXPECT_NE(all.find(file.string()), std::string::npos) << all;
    return all;
  }
  return "";
}

TEST(LanesFile, AWellFormedFileLoads) {
  EXPECT_EQ(
      lanesRefusal(R"({"a": {"shader": "x.hlsl", "shader_params": []}, "b": {"mode": "off"}})"),
      "");
}

TEST(LanesFile, KeysOfTheWrongTypeAreRefusedByName) {
  EXPECT_NE(lanesRefusal(R"({"a": {"shader": 5}})").find("a.shader: not a string"),
            std::string::npos);
  EXPECT_NE(lanesRefusal(R"({"a": {"shader": "x.hlsl", "shader_params": 5}})")
                .find("a.shader_params: not a list"),
            std::string::npos);
}

TEST(LanesFile, NamesAreNonEmptyPrintableAndShort) {
  EXPECT_NE(lanesRefusal(R"({"": {"mode": "off"}})").find("1 to 100 bytes"), std::string::npos);
  EXPECT_NE(lanesRefusal(R"({"a\u0000b": {"mode": "off"}})").find("without control characters"),
            std::string::npos);
  EXPECT_NE(lanesRefusal(R"({"a)" + std::string(200, 'x') + R"(": {"mode": "off"}})")
                .find("1 to 100 bytes"),
            std::string::npos);
}

// A lane's shader is relative to its lanes file: a path that climbs out says which folder it
// left, not the case's (a port beside the cases read as if the case were wrong).
TEST(LanesFile, AShaderLeavingTheLanesFolderIsRefusedNamingThatFolder) {
  cases::LaneParse lane;
  lane.shaderRoot = fs::path(TAA_TEST_OUT) / "lanes_file" / "ports";
  try {
    cases::parseCase(R"({"taa": {"shader": "../cases/x.hlsl"}})", "cases/c.json", lane);
    ADD_FAILURE() << "accepted";
  } catch (const cases::CaseError& e) {
    ASSERT_EQ(e.problems().size(), 1u);
    EXPECT_NE(e.problems()[0].find("cases/c.json: taa.shader: '../cases/x.hlsl' leaves " +
                                   fs::absolute(lane.shaderRoot).lexically_normal().string() +
                                   ", the folder of the lanes or presets file that names it"),
              std::string::npos)
        << e.problems()[0];
  }
}

TEST(LanesFile, TenThousandLanesAreRefusedBeforeAnyWork) {
  std::string json = "{";
  for (int i = 0; i < 10000; ++i)
    json += (i ? "," : "") + std::string("\"l") + std::to_string(i) + "\": {}";
  EXPECT_NE(lanesRefusal(json + "}").find("10000 lanes, over the limit of 256"), std::string::npos);
}

}  // namespace
}  // namespace taa
