// The generated headers' tables (taa_user.h, taa_user.hlsli) are what a user reads first: each
// row's name and description start in the same column as the rows around them.
#include <gtest/gtest.h>

#include <regex>
#include <set>
#include <sstream>
#include <vector>

#include "support/text.h"
#include "user/glsl_compiler.h"

namespace taa::user::user_header_docs_test {
namespace {

// Where each group of `row` starts, for every line that matches it: one entry when the table's
// columns line up.
std::set<std::vector<size_t>> columns(const std::string& header, const std::regex& row) {
  std::set<std::vector<size_t>> out;
  std::istringstream in(header);
  std::string line;
  std::smatch m;
  int rows = 0;
  while (std::getline(in, line))
    if (std::regex_search(line, m, row)) {
      std::vector<size_t> at;
      for (size_t g = 1; g < m.size(); ++g) at.push_back(size_t(m.position(g)));
      out.insert(at);
      ++rows;
    }
  EXPECT_GE(rows, 2) << "a table of fewer than two rows proves nothing";
  return out;
}

TEST(UserHeaderDocs, EveryTableRowIsAlignedWithItsNeighbours) {
  for (const char* name : {"taa_user.h", "taa_user.hlsli"}) {
    SCOPED_TRACE(name);
    const std::string header = test::readFile(userHeaderDir() / name);
    // Optional inputs: macro, name, description; capabilities and the inputs always declared:
    // a word, then the description.
    EXPECT_EQ(columns(header, std::regex("^//   TAA_USE_\\w+ +(taa_\\w+) +(\\S)")).size(), 1u);
    EXPECT_EQ(columns(header, std::regex("^//   TAA_SUPPORTS_\\w+ +(\\S)")).size(), 1u);
    EXPECT_EQ(columns(header, std::regex("^//   taa_\\w+ +(\\S)")).size(), 1u);
  }
}

}  // namespace
}  // namespace taa::user::user_header_docs_test
