// `taa-harness coverage`'s tables (harness/case/coverage.cpp): a value counts only where the
// case's mode and the key's rule make it count, and the resolve's constants are read from the
// trace a run writes.
#include "case/coverage.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "case/case_loader.h"

namespace taa {
namespace {

spec::CheckedCase coverageCase(const std::string& name, const std::string& body) {
  auto loaded = cases::parseCase(R"({"scene": {"builtin": "checkerboard"}, )" + body + "}",
                                 std::string(TAA_SOURCE_DIR) + "/cases/" + name + ".json");
  return loaded.spec;
}

std::vector<std::string> reaching(const std::vector<cases::CoverageRow>& rows,
                                  const std::string& key, const std::string& value) {
  for (const auto& r : rows)
    if (r.key == key && r.value == value) return r.cases;
  ADD_FAILURE() << "no row " << key << "=" << value;
  return {};
}

using Names = std::vector<std::string>;

TEST(Coverage, AValueCountsOnlyWhereTheModeAndTheRuleMakeItCount) {
  const std::vector<spec::CheckedCase> cases = {
      coverageCase("plain", R"("taa": {"history_filter": "bilinear"})"),
      coverageCase("culled", R"("taa": {"depth_culling": true, "depth_threshold": 0.2})"),
      coverageCase("accum", R"("taa": {"mode": "accumulate"})"),
      coverageCase("off", R"("taa": {"mode": "off"}, "post": {"fxaa": true})"),
      coverageCase("user", R"("taa": {"shader": "user/sample_count.comp"})")};
  const auto rows = cases::settingValueCoverage(cases);
  EXPECT_EQ(reaching(rows, "taa.history_filter", "bilinear"), Names{"plain"});
  // Accumulate runs the full path with its own history filter default.
  EXPECT_EQ(reaching(rows, "taa.history_filter", "catmull_rom_5"), Names{"culled"});
  // depth_threshold means something only with depth culling on.
  EXPECT_EQ(reaching(rows, "taa.depth_threshold", "other"), Names{"culled"});
  EXPECT_TRUE(reaching(rows, "taa.depth_threshold", "default").empty());
  // Accumulation fixes consistency on and rectification off: not settings it takes, so they
  // count for no value (the resolve's constants show them); consistency's tolerances it takes,
  // and its alpha 0.2 is not the declared default.
  EXPECT_TRUE(reaching(rows, "taa.consistency", "true").empty());
  EXPECT_TRUE(reaching(rows, "taa.rectify", "none").empty());
  EXPECT_EQ(reaching(rows, "taa.consistency_depth", "default"), Names{"accum"});
  EXPECT_EQ(reaching(rows, "taa.alpha", "other"), Names{"accum"});
  // No built-in resolve runs in mode off or under a user's shader: no taa.* value counts.
  EXPECT_EQ(reaching(rows, "taa.mode", "off"), Names{"off"});
  EXPECT_EQ(reaching(rows, "taa.shader", "set"), Names{"user"});
  EXPECT_EQ(reaching(rows, "taa.alpha", "default"), (Names{"plain", "culled"}));
  EXPECT_TRUE(reaching(rows, "taa.velocity_sampling", "pixel").empty());
}

TEST(Coverage, AMovingFloatIsBlendedOnlyWhereTheCaseGivesItAValueOfItsOwn) {
  const std::vector<spec::CheckedCase> cases = {
      coverageCase("moving", R"("taa": {"moving": {"alpha": 0.3, "to_px": 6}})"),
      coverageCase("still", R"("taa": {"alpha": 0.2})")};
  const auto rows = cases::settingValueCoverage(cases);
  EXPECT_EQ(reaching(rows, "taa.moving.alpha", "blended"), Names{"moving"});
  EXPECT_TRUE(reaching(rows, "taa.moving.rejection_alpha", "blended").empty());
  EXPECT_EQ(reaching(rows, "taa.moving.to_px", "other"), Names{"moving"});
  EXPECT_EQ(reaching(rows, "taa.moving.from_px", "default"), Names{"moving"});
}

TEST(Coverage, ResolveConstantsComeFromTheRunLogsTrace) {
  const std::map<std::string, std::vector<std::string>> logs = {
      {"a", {"pass taa_resolve", "taa_resolve spec constants: 0=2 1=1 19=1 5=0 7=1"}},
      {"b", {"pass taa_resolve", "taa_resolve spec constants: 0=1 1=1 19=0 5=3 7=0"}},
      {"c", {"pass tscmaa"}}};  // no built-in resolve: nothing traced
  const auto rows = cases::resolveBranchCoverage(logs);
  EXPECT_EQ(reaching(rows, "kResolve", "RESOLVE_FULL"), Names{"a"});
  EXPECT_EQ(reaching(rows, "kResolve", "RESOLVE_BASIC"), Names{"b"});
  EXPECT_TRUE(reaching(rows, "kResolve", "RESOLVE_PASS_THROUGH").empty());
  EXPECT_EQ(reaching(rows, "kUpsample", "true"), Names{"a"});
  EXPECT_EQ(reaching(rows, "kHistoryFilter", "HISTORY_FILTER_BILINEAR"), Names{"a"});
  EXPECT_EQ(reaching(rows, "kHistoryFilter", "HISTORY_FILTER_CATMULL_ROM_5"), Names{"b"});
  EXPECT_EQ(reaching(rows, "kDepthCulling", "true"), Names{"a"});
  // The no-history pipeline runs on every traced case's first frame.
  EXPECT_EQ(reaching(rows, "kHasHistory", "false"), (Names{"a", "b"}));
  EXPECT_TRUE(reaching(rows, "kShaped", "true").empty());
}

// A run's logs as `coverage --results` reads them: each case with a log kept under its name, a
// case without one left out, and a trace that is no trace refused naming its case's index.
TEST(Coverage, RunLogsAreKeptByCaseAndABadTraceNamesItsCase) {
  const auto kept = cases::checkedRunLogs({{"a", {"taa_resolve spec constants: 0=2"}},
                                           {"quiet", {}},
                                           {"b", {"pass tscmaa"}}});
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept.at("a"), std::vector<std::string>{"taa_resolve spec constants: 0=2"});
  EXPECT_EQ(kept.at("b"), std::vector<std::string>{"pass tscmaa"});
  try {
    cases::checkedRunLogs({{"a", {"pass x"}}, {"b", {"taa_resolve spec constants: 0=99999999999"}}});
    ADD_FAILURE() << "a constant of 11 digits was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("cases[1].log: ", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace taa
