// docs/case-format.md's "Every key" table is generated from the schema; a setting added,
// removed or re-documented without regenerating it fails here.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "case/case_loader.h"
#include "case/settings_table.h"

namespace {

// The table as the document holds it: from its header row to the first line that is no row.
std::string documentedKeyTable() {
  std::ifstream in(std::string(TAA_SOURCE_DIR) + "/docs/case-format.md");
  std::string line, table;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.rfind("| key | type | default |", 0) == 0) inside = true;
    if (inside && line.rfind("|", 0) != 0) break;
    if (inside) table += line + "\n";
  }
  return table;
}

TEST(SettingsTable, CaseFormatDocListsEverySettingAsTheSchemaSays) {
  const std::string generated = taa::cases::settingsMarkdownTable(taa::cases::settingsSchema());
  EXPECT_EQ(documentedKeyTable(), generated)
      << "docs/case-format.md's \"Every key\" table is out of date: replace it with the output of "
         "`taa-harness techniques --markdown`";
}

TEST(SettingsTable, RowsShowDefaultsRangesAndAllowedValues) {
  const auto schema = nlohmann::json::parse(R"([
    {"key": "a.n", "type": "number", "default": 0.5, "range": [0.0, 1.0], "doc": "a number", "impl": ""},
    {"key": "a.e", "type": "enum", "default": "x", "allowed": ["x", "y"], "doc": "a choice", "impl": ""},
    {"key": "a.v", "type": "vec3", "default": [1.0, 2.0, 3.0], "doc": "a vector", "impl": ""}])");
  std::istringstream rows(taa::cases::settingsMarkdownTable(schema));
  std::string line;
  std::getline(rows, line);
  std::getline(rows, line);
  std::getline(rows, line);
  EXPECT_EQ(line, "| `a.n` | number | `0.5` | 0.0 .. 1.0 | a number |");
  std::getline(rows, line);
  EXPECT_EQ(line, "| `a.e` | enum | `\"x\"` | x, y | a choice |");
  std::getline(rows, line);
  EXPECT_EQ(line, "| `a.v` | vec3 | `[1.0, 2.0, 3.0]` |  | a vector |");
}

}  // namespace
