// The seal on results.json (run/results_seal.h): an HMAC-SHA256 under the user's key, which a
// file edited since (a status turned to pass, a fingerprint made to match) no longer carries.
#include "run/results_seal.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace taa {
namespace {

namespace fs = std::filesystem;

// RFC 4231, test cases 1, 2 and 6 (a key longer than the block).
TEST(ResultsSeal, HmacSha256MatchesRfc4231) {
  EXPECT_EQ(run::hmacSha256Hex(std::string(20, '\x0b'), "Hi There"),
            "b0344c61d8db38535ca8afceaf0bf12b881dc200c9833da726e9376c2e32cff7");
  EXPECT_EQ(run::hmacSha256Hex("Jefe", "what do ya want for nothing?"),
            "5bdcc146bf60754e6a042426089575c75a003f089d2739839dec58b964ec3843");
  EXPECT_EQ(run::hmacSha256Hex(std::string(131, '\xaa'),
                               "Test Using Larger Than Block-Size Key - Hash Key First"),
            "60e431591ee0b67f0d8a26aacbf5b77f8e0bc6213728c5140546040f0ee37f54");
}

// A cache folder of the test's own, so the key made is this test's.
class SealTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(TAA_TEST_OUT) / "results_seal" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "out");
    if (const char* old = std::getenv("XDG_CACHE_HOME")) saved_ = old;
    ::setenv("XDG_CACHE_HOME", (dir_ / "cache").c_str(), 1);
  }
  void TearDown() override {
    if (saved_.empty())
      ::unsetenv("XDG_CACHE_HOME");
    else
      ::setenv("XDG_CACHE_HOME", saved_.c_str(), 1);
  }
  fs::path dir_;
  std::string saved_;
};

TEST_F(SealTest, AWrittenFileCarriesItsSealUntilEdited) {
  const fs::path results = dir_ / "out" / "results.json";
  const std::string text = R"({"cases": [{"name": "a", "status": "fail"}]})";
  ASSERT_EQ(run::writeSealedResults(results, text), "");
  // The key: made on first use, the user's alone.
  struct stat st {};
  ASSERT_EQ(::stat((dir_ / "cache" / "taa-harness" / "results-seal.key").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_EQ(st.st_size, 32);
  EXPECT_EQ(run::sealProblem(results, text), "");
  std::string edited = text;
  edited.replace(edited.find("fail"), 4, "pass");
  EXPECT_NE(run::sealProblem(results, edited).find("does not match"), std::string::npos);
  // Written without a seal (a merge of an edited shard), or its seal gone: not sealed.
  run::writeUnsealedResults(results, text);
  EXPECT_FALSE(fs::exists(run::sealPathOf(results)));
  EXPECT_NE(run::sealProblem(results, text), "");
}

TEST_F(SealTest, AnotherKeyOrAKeyOthersCanReadSealsNothing) {
  const fs::path results = dir_ / "out" / "results.json";
  ASSERT_EQ(run::writeSealedResults(results, "{}"), "");
  const fs::path key = dir_ / "cache" / "taa-harness" / "results-seal.key";
  fs::permissions(key, fs::perms::group_read, fs::perm_options::add);
  EXPECT_NE(run::sealProblem(results, "{}").find("mode 0600"), std::string::npos);
  fs::remove(key);  // another user's key (a new one is made)
  EXPECT_NE(run::sealProblem(results, "{}").find("does not match"), std::string::npos);
}

}  // namespace
}  // namespace taa
