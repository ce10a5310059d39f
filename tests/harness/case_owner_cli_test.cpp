// Two case files of one name in sibling folders share goldens/NAME: the manifest records which
// one the set belongs to (case_file), so blessing the other is refused while the first still
// exists, and running the other names the clash instead of calling its case file changed.
#include "golden/case_owner.h"
#include "golden/manifest.h"
#include "harness/cli_fixture.h"
#include "support/text.h"

namespace taa::case_owner_cli_test {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

TEST_F(HarnessCli, ASecondCaseOfTheSameNameCannotTakeTheFirstsGoldens) {
  for (const char* folder : {"a", "b"}) fs::create_directories(root_ / folder);
  std::ofstream(root_ / "a/same.json") << kSmallCase;
  std::string other = kSmallCase;
  other.replace(other.find("\"speed\": 0.5"), 12, "\"speed\": 0.7");
  std::ofstream(root_ / "b/same.json") << other;
  const std::string a = (root_ / "a/same.json").string(), b = (root_ / "b/same.json").string();
  const fs::path manifest = root_ / "goldens/same/manifest.json";
  ASSERT_EQ(harness("bless " + a + " --reason 'first'").exitCode, 0);
  EXPECT_EQ(golden::readManifest(manifest).caseFile, "a/same.json");
  const std::string blessed = test::readFile(manifest);

  // b's run fails naming the clash, not "changed since its goldens were blessed".
  auto r = harness("run " + b + " --out " + (root_ / "out").string());
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("holds the goldens of " + a), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("two case files named 'same.json' share one goldens folder"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("changed since"), std::string::npos) << r.output;
  // Its bless is refused as bad input and a's goldens stay as they were, both ways of blessing.
  for (const char* extra : {"", " --add-environment"}) {
    SCOPED_TRACE(extra);
    r = harness("bless " + b + " --reason 'second'" + extra);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find("REFUSED same: "), std::string::npos) << r.output;
    EXPECT_EQ(test::readFile(manifest), blessed);
  }
  // a's own run is unaffected, and so is a's twin in another checkout given these goldens.
  EXPECT_EQ(harness("run " + a + " --out " + (root_ / "out-a").string()).exitCode, 0);
  fs::create_directories(root_ / "checkout2/cases");
  fs::copy_file(root_ / "a/same.json", root_ / "checkout2/cases/same.json");
  r = harness("run " + (root_ / "checkout2/cases/same.json").string() + " --goldens " +
              (root_ / "goldens").string() + " --out " + (root_ / "out-2").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  // Once a is gone (moved away), b may take the folder.
  fs::rename(root_ / "a/same.json", root_ / "a/renamed.json");
  ASSERT_EQ(harness("bless " + b + " --reason 'a moved'").exitCode, 0);
  EXPECT_EQ(golden::readManifest(manifest).caseFile, "b/same.json");
}

// The manifest's case_file is read as untrusted text: only a folder and a file name.
TEST(CaseFileLabel, OnlyAFolderAndAFileName) {
  EXPECT_EQ(golden::caseFileLabel("/x/cases/foo.json"), "cases/foo.json");
  EXPECT_EQ(golden::caseFileLabel("/x/cases/./deeper/../foo.json"), "cases/foo.json");
  for (const char* ok : {"cases/foo.json", "foo.json"})
    EXPECT_TRUE(golden::validCaseFileLabel(ok)) << ok;
  for (const std::string& bad :
       {std::string(), std::string("../foo.json"), std::string("a/b/c.json"),
        std::string("/etc/passwd"), std::string("a/.."), std::string("a/"), std::string("a\0b", 3),
        std::string(600, 'x')})
    EXPECT_FALSE(golden::validCaseFileLabel(bad)) << bad;
}

}  // namespace
}  // namespace taa::case_owner_cli_test
