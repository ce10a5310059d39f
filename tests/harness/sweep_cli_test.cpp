// `taa-harness sweep` without --presets-file reads presets/presets.json of the nearest folder
// named cases above the case; a case under no such folder is told to pass the file.
#include "harness/cli_fixture.h"
#include "support/text.h"

namespace taa::sweep_cli_test {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

TEST_F(HarnessCli, SweepFindsThePresetsOfTheCasesFolderAboveTheCase) {
  fs::create_directories(root_ / "cases/presets");
  fs::create_directories(root_ / "cases/deeper");
  std::ofstream(root_ / "cases/presets/presets.json") << R"({"mine": {"taa": {"alpha": 0.2}}})";
  std::ofstream(root_ / "cases/deeper/small.json") << test::smallTaaCase();
  const fs::path out = root_ / "sweep";
  auto r = harness("sweep " + (root_ / "cases/deeper/small.json").string() + " --presets mine --out " +
                   out.string());
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(test::readFile(out / "sweep.csv").find("\nmine,"), std::string::npos)
      << test::readFile(out / "sweep.csv");
  // Outside any cases/ folder: refused, naming the option that gives the file.
  fs::create_directories(root_ / "elsewhere");
  std::ofstream(root_ / "elsewhere/small.json") << kSmallCase;
  r = harness("sweep " + (root_ / "elsewhere/small.json").string() + " --presets mine --out " +
              (root_ / "sweep2").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("is not under a cases/ folder; pass --presets-file"), std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace taa::sweep_cli_test
