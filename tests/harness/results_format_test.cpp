// results.json's one declaration (run/results_format.h) read and written by the same visitor:
// every key written is read back; a renamed, missing or unknown key and a file of another
// format_version are refused by name, through the one reader of a run's folder.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "run/results.h"
#include "run/results_format.h"
#include "run/run_folder.h"

namespace taa::results_format_test {

namespace fs = std::filesystem;

// Every field away from its default, both optional objects and all three optional lists present.
run::RunResults everyField() {
  run::RunResults r;
  r.device = "llvmpipe";
  r.fingerprint = "fp";
  r.environment = {"llvmpipe", "llvmpipe", "Mesa 22.3.6", "1.3.230", "x86-64-v4"};
  r.commit = "abc";
  r.build = "build-id 1 | spirv 2";
  r.suite = {{"a", "b"}, "00", 2, 3};
  r.notRun = 4;
  run::CaseResult c;
  c.name = "a";
  c.status = run::CaseStatus::Stale;
  c.goldenStatus = run::CaseStatus::NoGolden;
  c.goldenMode = "exact";
  c.referenceRmse = {0.5, 0.25};
  c.frameStats["traced_share"] = {0.1};
  c.frameSha256 = {"00"};
  c.sequenceCheck = {"signature", 5, 2, 3, 0.01, 4};
  c.firstDifference = {3, "frame 3 differs", "aa", "bb", "a/frame_0003.png", {{2, "a/x.png"}}};
  run::FrameComparison f;
  f.frame = 3;
  f.status = run::FrameStatus::WithinTolerance;
  f.metrics.psnr = std::numeric_limits<double>::infinity();
  f.metrics.rmse = 0.125;
  f.failures = {"rmse 0.1 > 0.01"};
  f.images.zoomW = 16;
  f.images.zoomChosen = true;
  c.frames.push_back(f);
  c.invariants.push_back({"finite", true, "ok", {{"nan_pixels", 0.0}, {"worst", -1.5}}});
  c.timings.push_back({"taa_resolve", 1.5, 2.5});
  r.cases.push_back(c);
  return r;
}

std::string refusal(const nlohmann::json& j) {
  try {
    run::runResultsFromJson(j);
  } catch (const run::ResultsFormatError& e) {
    return e.what();
  }
  return "(read without complaint)";
}

TEST(ResultsFormat, EveryKeyWrittenIsReadBack) {
  const nlohmann::json written = run::toJson(everyField());
  EXPECT_EQ(written.at("format_version"), run::kResultsFormatVersion);
  const run::RunResults back = run::runResultsFromJson(written);
  EXPECT_EQ(run::toJson(back), written);
  EXPECT_EQ(back.cases.at(0).status, run::CaseStatus::Stale);
  EXPECT_TRUE(std::isinf(back.cases.at(0).frames.at(0).metrics.psnr));
  EXPECT_EQ(back.suite.shardCount, 3);
  EXPECT_EQ(back.cases.at(0).invariants.at(0).values.at(1).second, -1.5);
}

TEST(ResultsFormat, OptionalObjectsAndListsAreLeftOutWhenTheCheckDidNotRun) {
  run::RunResults r;
  r.cases.emplace_back();
  const nlohmann::json j = run::toJson(r);
  for (const char* key : {"sequence_check", "first_difference", "frames", "invariants", "timings"})
    EXPECT_FALSE(j["cases"][0].contains(key)) << key;
  EXPECT_EQ(run::toJson(run::runResultsFromJson(j)), j);
}

TEST(ResultsFormat, MissingAndUnknownKeysAreRefusedByPath) {
  nlohmann::json j = run::toJson(everyField());
  j["cases"][0]["frames"][0]["images"]["zoom_golden_png"] = "";
  EXPECT_NE(refusal(j).find("cases[0].frames[0].images.zoom_golden_png: unknown key"),
            std::string::npos)
      << refusal(j);
  // At the top level too: a key of a newer format (or a typo) is not silently dropped.
  j = run::toJson(everyField());
  j["verdict_cache"] = true;
  EXPECT_NE(refusal(j).find("verdict_cache: unknown key (not in this format)"), std::string::npos)
      << refusal(j);
  j = run::toJson(everyField());
  j["cases"][0]["frames"][0]["metrics"].erase("rmse");
  EXPECT_NE(refusal(j).find("cases[0].frames[0].metrics.rmse: missing"), std::string::npos)
      << refusal(j);
  j = run::toJson(everyField());
  j["cases"][0]["status"] = "passed";
  EXPECT_NE(refusal(j).find("cases[0].status: 'passed' is not a value"), std::string::npos)
      << refusal(j);
  j = run::toJson(everyField());
  j["suite"]["shard"] = {4294967298ULL, 3};
  EXPECT_NE(refusal(j).find("suite.shard: expected a list of 2 whole numbers"), std::string::npos)
      << refusal(j);
}

class ResultsFolder : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(TAA_TEST_OUT) / "results_format" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  // Writes `j` as the folder's results.json and returns how the one reader refuses it.
  std::string folderRefusal(const nlohmann::json& j) {
    std::ofstream(dir_ / "results.json") << j.dump(1) << "\n";
    try {
      run::RunFolder(dir_).readResults("FIX");
    } catch (const run::RunFolderError& e) {
      return e.what();
    }
    return "(read without complaint)";
  }
  fs::path dir_;
};

TEST_F(ResultsFolder, ARenamedKeyInAWrittenFileIsRefusedByName) {
  nlohmann::json j = run::toJson(everyField());
  std::ofstream(dir_ / "results.json") << j.dump(1) << "\n";
  EXPECT_EQ(run::toJson(run::RunFolder(dir_).readResults("FIX")), j);
  j["cases"][0]["golden_state"] = j["cases"][0]["golden_status"];
  j["cases"][0].erase("golden_status");
  const std::string why = folderRefusal(j);
  EXPECT_NE(why.find((dir_ / "results.json").string() + ": cases[0].golden_status: missing"),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("; FIX"), std::string::npos) << why;
}

TEST_F(ResultsFolder, AnotherVersionOrNoneIsRefusedWithTheVersionNamed) {
  nlohmann::json j = run::toJson(everyField());
  j["format_version"] = run::kResultsFormatVersion + 1;
  std::string why = folderRefusal(j);
  EXPECT_NE(why.find("format_version: format " + std::to_string(run::kResultsFormatVersion + 1) +
                     ", where this build reads format " +
                     std::to_string(run::kResultsFormatVersion)),
            std::string::npos)
      << why;
  EXPECT_NE(why.find("run the cases again"), std::string::npos) << why;
  j.erase("format_version");  // a file of the harness before results.json had a version
  why = folderRefusal(j);
  EXPECT_NE(why.find("format_version: missing"), std::string::npos) << why;
  EXPECT_NE(why.find("run the cases again"), std::string::npos) << why;
}

}  // namespace taa::results_format_test
