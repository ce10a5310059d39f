// `taa-harness coverage`'s shader lines (harness/case/resolve_lines.cpp): a line counts as run
// by a case exactly when its block survives the case's specialization of taa_resolve.comp.
#include "case/resolve_lines.h"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "common/taa_settings.h"
#include "core/errors.h"

namespace taa {
namespace {

// The line number of the first line of shaders/FILE that contains `text`.
int lineOf(const std::string& file, const std::string& text) {
  std::ifstream in(std::string(TAA_SOURCE_DIR) + "/shaders/" + file);
  std::string line;
  for (int n = 1; std::getline(in, line); ++n)
    if (line.find(text) != std::string::npos) return n;
  ADD_FAILURE() << "no line with '" << text << "' in " << file;
  return 0;
}

const cases::SourceLine* row(const std::vector<cases::SourceLine>& rows, const std::string& file, int line) {
  for (const auto& r : rows)
    if (r.line == line && r.file.size() >= file.size() &&
        r.file.compare(r.file.size() - file.size(), file.size(), file) == 0)
      return &r;
  return nullptr;
}

std::vector<std::string> runBy(const std::vector<cases::SourceLine>& rows, const std::string& file, int line) {
  const auto* r = row(rows, file, line);
  EXPECT_NE(r, nullptr) << file << ":" << line << " has no code in the unspecialized resolve";
  return r ? r->cases : std::vector<std::string>{};
}

int specId(const std::string& key) {
#define ID_E(k, type, values, def, id, name, modes, reads, rule, text, doc, impl) if (key == #k) return id;
#define ID_B(k, def, id, name, modes, reads, rule, text, doc, impl) if (key == #k) return id;
#define ID_F(k, def, lo, hi, slot, name, modes, rule, text, doc, impl)
  TAA_SETTINGS(ID_E, ID_B, ID_F)
  ADD_FAILURE() << "no constant for taa." << key;
  return -1;
}

using Names = std::vector<std::string>;

class ResolveLines : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // Two cases on the full resolve that differ in the history filter only; the rest of their
    // constants keep the shader's defaults.
    const int filter = specId("history_filter");
    rows_ = new std::vector<cases::SourceLine>(cases::resolveLineCoverage(
        cases::loadResolveWithLines(),
        {{"bspline", {{TAA_SPEC_RESOLVE, 2}, {filter, 1}}}, {"bilinear", {{TAA_SPEC_RESOLVE, 2}, {filter, 0}}}}));
  }
  static void TearDownTestSuite() { delete rows_; }
  static std::vector<cases::SourceLine>* rows_;
};
std::vector<cases::SourceLine>* ResolveLines::rows_ = nullptr;

TEST_F(ResolveLines, ABranchsBodyRunsOnlyWhereTheCaseSelectsIt) {
  const std::string f = "taa/history_filter.glsl";
  EXPECT_EQ(runBy(*rows_, f, lineOf(f, "vec2 w3 = f3 / 6.0;")), Names{"bspline"});  // B-spline weights
  EXPECT_EQ(runBy(*rows_, f, lineOf(f, "else h = historyBilinear(tex, uv);")), Names{"bilinear"});
  // Condition and call on one line: the condition runs where the chain gets that far (not
  // for bspline, its first branch), the call in neither.
  const int both = lineOf(f, "h = historyCatmullRom16(tex, uv, size);");
  EXPECT_EQ(runBy(*rows_, f, both), Names{"bilinear"});
  ASSERT_NE(row(*rows_, f, both), nullptr);
  EXPECT_TRUE(row(*rows_, f, both)->partly);
  EXPECT_FALSE(row(*rows_, f, lineOf(f, "vec2 w3 = f3 / 6.0;"))->partly);
}

TEST_F(ResolveLines, AConditionFoldedAwayStillCountsAsRun) {
  // The comparison folds to a constant in both specializations and leaves no instruction of
  // its own; its block is reached all the same.
  const std::string f = "taa/history_filter.glsl";
  EXPECT_EQ(runBy(*rows_, f, lineOf(f, "if (s.history_filter == HISTORY_FILTER_BSPLINE)")),
            (Names{"bilinear", "bspline"}));
}

TEST_F(ResolveLines, EveryCaseAlsoRunsTheNoHistoryPipeline) {
  // Traced with history; the first frame's pipeline (kHasHistory false) writes the current
  // colour as it is and returns.
  const std::string f = "taa_resolve.comp";
  EXPECT_EQ(runBy(*rows_, f, lineOf(f, "writeOutput(s, q, current, 1.0, 0.0, vec2(0.0));")),
            (Names{"bilinear", "bspline"}));
  // Pass-through is a path neither case takes.
  EXPECT_TRUE(runBy(*rows_, f, lineOf(f, "imageStore(historyOut, q, texelFetch(colorTex, min(q, hi), 0));")).empty());
}

TEST(ResolveLinesInput, ABadModuleIsAnEnvironmentError) {
  EXPECT_THROW(cases::resolveLineCoverage({1, 2, 3}, {}), EnvironmentError);
  std::vector<uint32_t> truncated = {0x07230203u, 0x00010500u, 0, 10, 0, (9u << 16) | 8u};
  EXPECT_THROW(cases::resolveLineCoverage(truncated, {}), EnvironmentError);
}

}  // namespace
}  // namespace taa
