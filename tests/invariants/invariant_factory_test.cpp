// The factory and the case-file rule: listed invariants must apply to the case, and an
// invariant's parameters may only be set when it is listed.
#include "case/case_error.h"
#include "case/case_loader.h"
#include "invariants/invariant_fixtures.h"

using namespace taa;
using namespace taa::invariants;
using namespace taa::invariants::fixtures;
using spec::InvariantKind;

namespace {

std::vector<std::string> problemsOf(const std::string& json) {
  try {
    cases::parseCase(json, "cases/t.json");
  } catch (const cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

}  // namespace

TEST(InvariantFactory, EveryKindHasAnInvariantNamedAfterIt) {
  for (const auto& n : spec::enumNames(InvariantKind{})) {
    auto inv = makeInvariant(n.value, staticCase());
    ASSERT_NE(inv, nullptr) << n.name;
    EXPECT_EQ(inv->finish().name, n.name);
  }
}

TEST(InvariantFactory, NeedsMatchWhatEachInvariantReads) {
  EXPECT_TRUE(needsOf(InvariantKind::HistoryBounded).current);
  const Needs ghost = needsOf(InvariantKind::NoGhosting);
  EXPECT_TRUE(ghost.reference && ghost.ids && !ghost.velocity);
  const Needs stab = needsOf(InvariantKind::TemporalStability);
  EXPECT_TRUE(stab.reference && stab.ids && stab.velocity);
  EXPECT_TRUE(needsOf(InvariantKind::Converges).reference);
  EXPECT_TRUE(needsOf(InvariantKind::Energy).reference);
  const Needs fin = needsOf(InvariantKind::Finite);
  EXPECT_FALSE(fin.reference || fin.current || fin.ids || fin.velocity || fin.secondRun);
  EXPECT_FALSE(needsOf(InvariantKind::BitStable).reference);
}

TEST(InvariantValidation, InapplicableInvariantIsAProblemAtItsKey) {
  const auto p = problemsOf(
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
      problemsOf(R"({"checks": {"invariants": ["energy"], "no_ghosting": {"frames": 4}}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(
      contains(p[0],
               "checks.no_ghosting: parameters of no_ghosting are set but checks.invariants does "
               "not list it"))
      << p[0];
}

TEST(InvariantValidation, DuplicateIsAProblem) {
  const auto p = problemsOf(R"({"checks": {"invariants": ["energy", "energy"]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_TRUE(contains(p[0], "checks.invariants[1]: 'energy' is listed twice")) << p[0];
}

TEST(InvariantValidation, ApplicableInvariantsWithTheirParametersLoad) {
  EXPECT_TRUE(problemsOf(R"({
    "movers": [{"speed": 2}],
    "checks": {"invariants": ["history_bounded", "no_ghosting", "temporal_stability", "finite",
                             "energy", "determinism"],
               "no_ghosting": {"frames": 4}, "energy": {"epsilon": 0.05}}})")
                  .empty());
  EXPECT_TRUE(problemsOf(R"({"jitter": {"pattern": "none"},
    "checks": {"invariants": ["bit_stable"], "bit_stable": {"after_frame": 8}}})")
                  .empty());
}

TEST(InvariantValidation, EveryListedProblemIsReported) {
  const auto p = problemsOf(R"({"checks": {"invariants": ["no_ghosting", "bit_stable", "converges"],
    "temporal_stability": {"factor": 2}}})");
  ASSERT_EQ(p.size(), 3u);  // no movers; halton jitter; parameters without listing
  EXPECT_TRUE(contains(p[0], "checks.invariants[0]: no_ghosting")) << p[0];
  EXPECT_TRUE(contains(p[1], "checks.invariants[1]: bit_stable")) << p[1];
  EXPECT_TRUE(contains(p[2], "checks.temporal_stability: ")) << p[2];
}
