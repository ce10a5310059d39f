// The factory and the case-file rule: listed invariants must apply to the case, and an
// invariant's parameters may only be set when it is listed.
#include <algorithm>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "invariants/invariant_fixtures.h"
#include "support/case_problems.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;

TEST(InvariantTable, EveryRowBuildsAnInvariantReportedUnderItsName) {
  std::vector<std::string> seen;
  for (const auto* row : invariantTable()) {
    ASSERT_NE(row->make, nullptr) << row->name;
    EXPECT_EQ(findInvariant(row->name), row);
    EXPECT_EQ(std::count(seen.begin(), seen.end(), row->name), 0)
        << row->name << " is in the table twice";
    seen.push_back(row->name);
    // Through the runner's driver: the outcome carries the row's name even with no frames.
    EXPECT_EQ(runAll(row->name, staticCase(), {}).name, row->name);
  }
  EXPECT_EQ(seen.size(), 11u);
  EXPECT_EQ(findInvariant("no_such_invariant"), nullptr);
  EXPECT_THROW(invariantInfo("no_such_invariant"), std::invalid_argument);
}

TEST(InvariantTable, EveryParameterObjectBelongsToOneRow) {
  // checks.<params> of each row is validated against the listing (see InvariantValidation).
  std::vector<std::string> params;
  for (const auto* row : invariantTable())
    if (row->params) params.push_back(row->params);
  EXPECT_EQ(params, (std::vector<std::string>{"no_ghosting", "converges", "temporal_stability",
                                              "energy", "bit_stable"}));
}

TEST(InvariantRunner, FromFrameHoldsBackWarmUpExceptFromInvariantsThatJudgeEveryFrame) {
  auto s = staticCase();
  s.checks.from_frame = 3;
  s.checks.invariants = {"finite", "bit_stable"};
  run::InvariantRun checks(s);
  EXPECT_TRUE(checks.judgesWarmUp());  // finite: a NaN counts whenever it appears
  EXPECT_FALSE(checks.readsImages(2));
  EXPECT_TRUE(checks.readsImages(3));
  s.checks.invariants = {"bit_stable"};
  EXPECT_FALSE(run::InvariantRun(s).judgesWarmUp());
  s.checks.invariants = {};
  EXPECT_FALSE(run::InvariantRun(s).readsImages(5));
}

TEST(InvariantFactory, NeedsMatchWhatEachInvariantReads) {
  using C = Capture;
  EXPECT_EQ(needsOf("history_bounded").captures, CaptureSet({C::Current}));
  EXPECT_EQ(needsOf("no_ghosting").captures, CaptureSet({C::Reference, C::Ids}));
  EXPECT_EQ(needsOf("temporal_stability").captures,
            CaptureSet({C::Reference, C::Ids, C::Velocity}));
  EXPECT_EQ(needsOf("converges").captures, CaptureSet({C::Reference}));
  EXPECT_EQ(needsOf("energy").captures, CaptureSet({C::Reference}));
  EXPECT_EQ(needsOf("adaptive_unmarked").captures, CaptureSet({C::Resolved, C::Segmentation}));
  EXPECT_EQ(needsOf("tscmaa_non_edge").captures, CaptureSet({C::Current, C::Cmaa, C::EdgeMask}));
  const Needs fin = needsOf("finite");
  EXPECT_TRUE(fin.captures.empty());
  EXPECT_FALSE(fin.secondRun);
  EXPECT_TRUE(needsOf("bit_stable").captures.empty());
  EXPECT_FALSE(needsOf("bit_stable").secondRun);
}

TEST(InvariantValidation, InapplicableInvariantIsAProblemAtItsKey) {
  const auto p = test::caseProblems(
      R"({"taa": {"rectify": "none"}, "checks": {"invariants": ["finite", "history_bounded"]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(
      contains(p[0],
               "cases/t.json: checks.invariants[1]: history_bounded checks the clamp/clip box, but "
               "taa.rectify is none; remove it from checks.invariants or enable taa.rectify"))
      << p[0];
}

TEST(InvariantValidation, ParametersOfAnUnlistedInvariantAreAProblem) {
  const auto p =
      test::caseProblems(R"({"checks": {"invariants": ["energy"], "no_ghosting": {"frames": 4}}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(
      contains(p[0],
               "checks.no_ghosting: parameters of no_ghosting are set but checks.invariants does "
               "not list it"))
      << p[0];
}

TEST(InvariantValidation, DuplicateIsAProblem) {
  const auto p = test::caseProblems(R"({"checks": {"invariants": ["energy", "energy"]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(contains(p[0], "checks.invariants[1]: 'energy' is listed twice")) << p[0];
}

TEST(InvariantValidation, ApplicableInvariantsWithTheirParametersLoad) {
  EXPECT_TRUE(test::caseProblems(R"({
    "movers": [{"speed": 2}],
    "checks": {"invariants": ["history_bounded", "no_ghosting", "temporal_stability", "finite",
                             "energy", "determinism"],
               "no_ghosting": {"frames": 4}, "energy": {"epsilon": 0.05}}})")
                  .empty());
  EXPECT_TRUE(test::caseProblems(R"({"jitter": {"pattern": "none"},
    "checks": {"invariants": ["bit_stable"], "bit_stable": {"after_frame": 8}}})")
                  .empty());
}

TEST(InvariantValidation, EveryListedProblemIsReported) {
  const auto p = test::caseProblems(R"({"checks": {"invariants": ["no_ghosting", "bit_stable", "converges"],
    "temporal_stability": {"factor": 2}}})");
  ASSERT_EQ(p.size(), 3u);  // no movers; halton jitter; parameters without listing
  EXPECT_TRUE(contains(p[0], "checks.invariants[0]: no_ghosting")) << p[0];
  EXPECT_TRUE(contains(p[1], "checks.invariants[1]: bit_stable")) << p[1];
  EXPECT_TRUE(contains(p[2], "checks.temporal_stability: ")) << p[2];
}

TEST(InvariantValidation, UnknownNameIsAProblemWithTheTableAndAGuess) {
  const auto p = test::caseProblems(R"({"checks": {"invariants": ["finite", "energi"]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(contains(
      p[0], "cases/t.json: checks.invariants[1]: 'energi' is not one of history_bounded, "))
      << p[0];
  EXPECT_TRUE(contains(p[0], "; did you mean 'energy'?")) << p[0];
}

TEST(InvariantValidation, SchemaListsTheTableAsTheAllowedNames) {
  for (const auto& row : cases::settingsSchema())
    if (row["key"] == "checks.invariants") {
      EXPECT_EQ(row["type"], "list of enum");
      EXPECT_EQ(row["allowed"].get<std::vector<std::string>>(), invariantNames());
      return;
    }
  ADD_FAILURE() << "no checks.invariants row";
}
