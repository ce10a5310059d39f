// ShaderUseRecord (api/device.h): the SPIR-V a case's renderers load, which the run log lists
// and the mutation loop reads to know which cases a shader mutant can affect. A name missed
// (a cached pipeline, a nested record) would let a mutant skip a case that runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "api/device.h"
#include "support/gpu.h"

namespace taa {
namespace {

bool has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

const char* const kPostCase = R"({"render": {"width": 32, "height": 18}, "script": {"frames": 2},
  "output": {"frames": [1]}, "post": {"fxaa": true}})";

TEST(ShaderUse, NamesWhatTheCaseLoadsAndNothingElse) {
  const auto spec = test::caseFromJson(kPostCase);
  std::vector<std::string> first, again;
  {
    const ShaderUseRecord record;
    test::renderCase(spec);
    first = record.names();
  }
  EXPECT_TRUE(has(first, "taa_resolve.comp")) << ::testing::PrintToString(first);
  EXPECT_TRUE(has(first, "gbuffer.vert"));
  EXPECT_TRUE(std::any_of(first.begin(), first.end(),
                          [](const std::string& n) { return n.rfind("fxaa", 0) == 0; }))
      << "the post pass's shader: " << ::testing::PrintToString(first);
  EXPECT_FALSE(has(first, "reference_accumulate.comp")) << "no check needs a reference";
  EXPECT_TRUE(std::is_sorted(first.begin(), first.end()));
  {
    // The device keeps the pipelines now: a second render reuses them and must name them all.
    const ShaderUseRecord record;
    test::renderCase(spec);
    again = record.names();
  }
  EXPECT_EQ(first, again);
}

TEST(ShaderUse, AnInnerRecordsNamesReachTheOuterOne) {
  const ShaderUseRecord outer;
  std::vector<std::string> inner;
  {
    const ShaderUseRecord record;
    test::renderCase(test::caseFromJson(kPostCase));
    inner = record.names();
  }
  ASSERT_FALSE(inner.empty());
  EXPECT_EQ(outer.names(), inner);
}

TEST(ShaderUse, NothingIsRecordedWithoutARecord) {
  test::renderCase(test::caseFromJson(kPostCase));
  const ShaderUseRecord record;  // installed after the render
  EXPECT_TRUE(record.names().empty());
}

}  // namespace
}  // namespace taa
